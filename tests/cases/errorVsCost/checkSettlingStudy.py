#!/usr/bin/env python3
"""The error study of a case with a closed form (runSettlingStudy.sh):
colloidErrorStudy's outputs against what the closed form says.

Asserted, for each quantity of each setting with a scheme order:
  - the observed order (from the two finest rungs' errors against the
    closed form) within 0.2 of the scheme's order (trapezoidal drag: 2);
  - Richardson's order from the three finest rungs within 0.2 of it too,
    and the ladder found in its asymptotic range;
  - Richardson's estimate of each rung's error within a factor 2 of its
    true error against the closed form;
  - the CSV, Markdown and PNG files written.

usage: checkSettlingStudy.py studyOutputDir
"""
import csv
import os
import sys

ORDER_TOL = 0.2
FACTOR = 2.0


def main():
    out = sys.argv[1]
    for name in ("errorStudy.csv", "errorStudyOrders.csv", "errorStudy.md", "errorStudy.png"):
        if not os.path.getsize(os.path.join(out, name)) > 0:
            print("FAIL: %s missing or empty" % name)
            return 1
    ok = True
    orders = list(csv.DictReader(open(os.path.join(out, "errorStudyOrders.csv"))))
    if not orders:
        print("FAIL: no quantity analysed")
        return 1
    for row in orders:
        scheme = float(row["schemeOrder"])
        observed, rich = float(row["observedOrder"]), float(row["richardsonOrder"])
        good = row["source"] == "closed form" and abs(observed - scheme) <= ORDER_TOL \
            and abs(rich - scheme) <= ORDER_TOL and row["asymptotic"] == "yes"
        print("%s/%s: observed order %.3f, Richardson %.3f (asymptotic: %s), scheme %g: %s"
              % (row["setting"], row["quantity"], observed, rich, row["asymptotic"],
                 scheme, "ok" if good else "FAIL"))
        ok = ok and good
    rungs = list(csv.DictReader(open(os.path.join(out, "errorStudy.csv"))))
    for row in rungs:
        for q in (r["quantity"] for r in orders if r["setting"] == row["setting"]):
            true, est = float(row[q + "_error"]), float(row[q + "_richardsonError"])
            ratio = est/true
            good = 1/FACTOR <= ratio <= FACTOR
            print("%s %s: %s error %.4g, Richardson's estimate %.4g (ratio %.3f): %s"
                  % (row["setting"], row["value"], q, true, est, ratio, "ok" if good else "FAIL"))
            ok = ok and good
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
