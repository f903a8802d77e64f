#!/usr/bin/env python3
"""The slot coater's error study at test size (runSlotCoaterStudy.sh):
what every ladder must show, from colloidErrorStudy's outputs.

Asserted:
  - the CSV, orders CSV, Markdown and PNG files are written;
  - every rung ran (the ladders stay within the start-up limits);
  - each ladder holds the case's default once, marked;
  - where the tool calls a ladder converging (its error from Richardson,
    in or not checkably out of its asymptotic range), the quantity
    converges monotonically over the rungs: successive differences, fine
    to coarse, keep their sign and grow with the refinement measure;
  - where it says 'no change', the rungs agree to 1e-12 (relative);
  - every rung's error is known except where the ladder is not in its
    asymptotic range (then the finest rung's is not);
  - measuredErrors records the study's context (errorStudyDict): the form
    of the colloid cut-offs and the zeta potential with the case's values
    (src/python/foamDict.py reads both files).

usage: checkSlotCoaterStudy.py studyOutputDir
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)),
                                "..", "..", "..", "src", "python"))
import foamDict  # noqa: E402


def main():
    out = sys.argv[1]
    for name in ("errorStudy.csv", "errorStudyOrders.csv", "errorStudy.md", "errorStudy.png"):
        path = os.path.join(out, name)
        if not (os.path.exists(path) and os.path.getsize(path) > 0):
            print("FAIL: %s missing or empty" % name)
            return 1
    ok = True
    rungs = list(csv.DictReader(open(os.path.join(out, "errorStudy.csv"))))
    orders = list(csv.DictReader(open(os.path.join(out, "errorStudyOrders.csv"))))
    settings = sorted(set(r["setting"] for r in rungs))
    for s in settings:
        mine = sorted((r for r in rungs if r["setting"] == s), key=lambda r: float(r["h"]))
        failed = [r["value"] for r in mine if r["status"] != "ok"]
        defaults = [r["value"] for r in mine if r["default"] == "1"]
        good = not failed and len(defaults) == 1
        print("%s: %d rungs, failed %s, default %s: %s"
              % (s, len(mine), failed or "none", defaults, "ok" if good else "FAIL"))
        ok = ok and good
        for o in (o for o in orders if o["setting"] == s):
            q = o["quantity"]
            values = [float(r[q]) for r in mine]
            scale = max(abs(v) for v in values) or 1.0
            diffs = [b - a for a, b in zip(values, values[1:])]
            if o["source"] == "no change":
                good = all(abs(d) <= 1e-12*scale for d in diffs)
                verdict = "no change"
            elif o["source"] == "Richardson":
                good = all((d > 0) == (diffs[0] > 0) and d != 0 for d in diffs) and \
                    all(abs(b) >= abs(a) for a, b in zip(diffs, diffs[1:]))
                verdict = "order %s, asymptotic %s, differences %s" % (
                    o["richardsonOrder"], o["asymptotic"], ", ".join("%.3g" % d for d in diffs))
            else:
                good = True
                verdict = o["source"]
            unknown = [r["value"] for r in mine if r[q + "_error"] == "–"]
            good = good and (not unknown or (o["source"] == "finest rung" and len(unknown) == 1))
            print("    %s: %s: %s" % (q, verdict, "ok" if good else "FAIL"))
            ok = ok and good

    # The study's context, with the case's values
    case = os.path.dirname(os.path.abspath(out))
    measured = foamDict.read(os.path.join(out, "measuredErrors"))
    parameters = foamDict.read(os.path.join(case, "system", "slotCoaterParameters"))
    context = measured.get("context")
    recorded = {e.get("entry"): e.get("value") for e in context.values()
                if isinstance(e, dict)} if isinstance(context, dict) else {}
    for name in ("colloidCutoffForm", "zetaPotential"):
        good = name in recorded and recorded[name] == parameters.get(name)
        print("measuredErrors context %s: %r (the case's %r): %s"
              % (name, recorded.get(name), parameters.get(name), "ok" if good else "FAIL"))
        ok = ok and good

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
