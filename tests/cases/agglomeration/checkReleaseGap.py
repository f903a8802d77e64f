#!/usr/bin/env python3
"""The wavering pair and wall contact of runReleaseGapTest.sh against
their closed forms: gap = 7 - 6 sin(2 pi t/P) nm, P = 10 us, touching below
5 nm, released at 10 nm.  A contact forms at phase f1 = asin(1/3)/(2 pi)
and ends at 7/12 (sin = -1/2); one that ended with the gap back at 5 nm
(phase 1/2 - f1) would be the release gap ignored.  Asserted: 3 pair and 3
wall contacts formed and ended, each lasting (7/12 - f1) P within one
analysis interval (each end is seen up to one interval late); at every
analysis inside the contact's window and with the gap above 5 nm (held by
the release gap), 1 pair contact, 1 wall contact, 2 particles with one
contact each and one agglomerate of 2.  A resumed run's folders are
joined (src/python/contactAnalysis.py).

usage: checkReleaseGap.py caseDir"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "src", "python"))
import contactAnalysis  # noqa: E402

P = 1e-5            # s
INTERVAL = 2e-8     # s: one coupling step
F1 = math.asin(1.0/3)/(2*math.pi)
END = 7.0/12


def gap_nm(t):
    return 7 - 6*math.sin(2*math.pi*t/P)


def main():
    data = contactAnalysis.read(sys.argv[1])
    rows, ended = data["contacts"], data["durations"]
    ok = len(rows) > 1000
    total = {k: int(sum(r[k] for r in rows))
             for k in ("pairFormed", "pairBroken", "wallFormed", "wallBroken")}
    print("%d analyses to %g s; %s" % (len(rows), rows[-1]["time"], total))
    ok = ok and all(v == 3 for v in total.values())

    expected = (END - F1)*P
    for kind in ("pair", "wall"):
        d = [r["duration"] for r in ended if r["kind"] == kind]
        print("%s contacts ended: %d, durations %s s, closed form %.6g s (released at the "
              "touching gap: %.6g s)" % (kind, len(d), ["%.6g" % x for x in d], expected,
                                         (0.5 - 2*F1)*P))
        ok = ok and len(d) == 3 and all(abs(x - expected) <= INTERVAL*1.001 for x in d)

    held, bad = 0, []
    for r in rows:
        t = r["time"]
        phase = math.fmod(t, P)/P
        if F1 + INTERVAL/P < phase < END - INTERVAL/P and gap_nm(t) >= 5:
            held += 1
            got = (r["pairContacts"], r["wallContacts"], r["with1"], r["agglomerates"],
                   r["largestAgglomerate"])
            if got != (1, 1, 2, 1, 2):
                bad.append((r["time"], got))
    print("analyses held by the release gap: %d; rows other than 1 pair and 1 wall contact, "
          "2 particles with one, one agglomerate of 2: %s" % (held, bad[:5] or "none"))
    ok = ok and held > 100 and not bad
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
