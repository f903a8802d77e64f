#!/usr/bin/env python3
"""A touching pair carried across the periodic face
(runPeriodicCrossingTest.sh): at every analysis one particle contact, none
formed or broken, one agglomerate of 2; at the end both particles present,
each having moved by more than the 1 um it needed to cross the face, and
moving with the flow (0.1 m/s within 1 %).

usage: checkPeriodicCrossing.py caseDir"""
import csv
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "src", "python"))
import particleCloud  # noqa: E402

U = 0.1


def main():
    case = sys.argv[1]
    files = glob.glob(os.path.join(case, "postProcessing", "contactAnalysis", "*", "contacts.csv"))
    rows = list(csv.DictReader(l for l in open(files[0]) if not l.startswith("#")))
    bad = [r["time"] for r in rows
           if (r["pairContacts"], r["pairFormed"], r["pairBroken"], r["agglomerates"],
               r["largestAgglomerate"], r["particles"]) != ("1", "0", "0", "1", "2", "2")]
    print("%d analyses over %s s; rows other than one contact, none formed or broken, "
          "one agglomerate of 2: %s" % (len(rows), rows[-1]["time"], bad or "none"))
    ok = not bad and len(rows) > 100
    times = particleCloud.write_times(case)
    first, last = particleCloud.read(times[0]), particleCloud.read(times[-1])
    for i in range(2):
        x0, x1 = first["position"][i][0], last["position"][i][0]
        v = last["velocity"][i][0]
        crossed = (x1 < x0) if x0 > 50e-6 else (x1 - x0 > 1e-6)  # wrapped or moved on
        print("particle %d: x %.6g -> %.6g m, v_x %.6g m/s" % (first["id"][i], x0, x1, v))
        ok = ok and crossed and abs(v - U) <= 0.01*U
    ok = ok and first["id"] == last["id"] == [1, 2]
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
