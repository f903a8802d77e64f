#!/usr/bin/env python3
"""Particle bookkeeping of a colloidDEMFoam run: at every write of
log.colloidDEMFoam, present = inserted - removed exactly.  The three counts
are independent: present is LIGGGHTS' atom count, inserted is counted by
the coupling as particles first appear, removed by the DEM's outflow fix.
The run must have inserted and removed particles (else the check says
nothing), and every write must have its particle file with 'present'
particles.

usage: checkBookkeeping.py CASE     (writes CASE/bookkeeping.txt)
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "coupling"))
import particleVTK  # noqa: E402

LINE = re.compile(r"Particles: present (\d+), inserted (\d+), removed (\d+)")


def main():
    case = sys.argv[1]
    counts = [tuple(int(g) for g in m.groups())
              for m in LINE.finditer(open(os.path.join(case, "log.colloidDEMFoam")).read())]
    files = particleVTK.all_files(case)
    ok = len(counts) == len(files) and len(counts) > 2
    print("%d writes, %d particle files" % (len(counts), len(files)))
    for (present, inserted, removed), path in zip(counts, files):
        nFile = len(particleVTK.read(path)["position"])
        good = present == inserted - removed and nFile == present
        ok = ok and good
        print("%-28s present %6d  inserted %6d  removed %4d  in file %6d  %s"
              % (os.path.basename(path), present, inserted, removed, nFile,
                 "ok" if good else "MISMATCH"))
    present, inserted, removed = counts[-1]
    if inserted == 0 or removed == 0:
        print("the run must insert and remove particles")
        ok = False

    velocity = particleVTK.read(files[-1])["velocity"]
    mean = [sum(v[k] for v in velocity)/len(velocity) for k in range(3)]
    with open(os.path.join(case, "bookkeeping.txt"), "w") as f:
        f.write("%d %d %d %.10g %.10g %.10g\n"
                % ((present, inserted, removed) + tuple(mean)))
    print("final mean particle velocity (%.6g %.6g %.6g) m/s" % tuple(mean))
    print("bookkeeping: %s" % ("passed" if ok else "FAILED"))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
