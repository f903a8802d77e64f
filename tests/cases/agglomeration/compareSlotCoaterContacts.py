#!/usr/bin/env python3
"""The slot-coater tutorial's contact analysis at test size, serial
against 2 ranks from the same fill (the fixtures of case.slotCoater.*):

  - both runs wrote the time series (contacts.csv, contactDurations.csv,
    agglomerateSizes.csv) and the plot (contactAnalysis.png, Allrun);
  - the fill holds no contact and no agglomerate (its minimum gap):
    the first row of each run has 0 particle contacts;
  - at the start the two runs agree exactly (the same particles);
  - over the run, the analyses of the same times agree in particle and
    wall contacts within 2 + 10 % (the runs part by round-off: DEM
    trajectories are chaotic; measured: identical at test size) and the
    totals of contacts formed within the same bound.

usage: compareSlotCoaterContacts.py serialCase parallelCase"""
import csv
import glob
import os
import sys


def rows(case):
    files = glob.glob(os.path.join(case, "postProcessing", "contactAnalysis", "*", "contacts.csv"))
    if len(files) != 1:
        raise SystemExit("FAIL: %s: expected one contacts.csv, found %s" % (case, files))
    folder = os.path.dirname(files[0])
    for name in ("contactDurations.csv", "agglomerateSizes.csv"):
        if not os.path.exists(os.path.join(folder, name)):
            raise SystemExit("FAIL: %s missing in %s" % (name, folder))
    if not os.path.getsize(os.path.join(case, "contactAnalysis.png")) > 0:
        raise SystemExit("FAIL: no contactAnalysis.png in %s" % case)
    with open(files[0]) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def within(a, b):
    return abs(a - b) <= 2 + 0.1*max(abs(a), abs(b))


def main():
    serial, parallel = rows(sys.argv[1]), rows(sys.argv[2])
    ok = True

    def check(what, good):
        nonlocal ok
        print("%-60s %s" % (what, "ok" if good else "FAIL"))
        ok = ok and good

    check("fill without contacts: serial %s, parallel %s particle contacts at the start"
          % (serial[0]["pairContacts"], parallel[0]["pairContacts"]),
          int(serial[0]["pairContacts"]) == 0 and int(parallel[0]["pairContacts"]) == 0)
    check("first rows identical", serial[0] == parallel[0])
    times = {r["time"]: r for r in parallel}
    common = [(r, times[r["time"]]) for r in serial if r["time"] in times]
    check("%d analyses at common times (of %d, %d)" % (len(common), len(serial), len(parallel)),
          len(common) >= 0.9*max(len(serial), len(parallel)))
    worst = 0.0
    for s, p in common:
        for key in ("pairContacts", "wallContacts", "agglomeratedParticles"):
            a, b = float(s[key]), float(p[key])
            worst = max(worst, abs(a - b))
            if not within(a, b):
                check("t = %s s: %s %g (serial) against %g (2 ranks)" % (s["time"], key, a, b), False)
    print("largest difference of a count at a common time: %g" % worst)
    for key in ("pairFormed", "wallFormed"):
        a = sum(float(s[key]) for s, _ in common)
        b = sum(float(p[key]) for _, p in common)
        check("%s in all: %g (serial), %g (2 ranks)" % (key, a, b), within(a, b))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
