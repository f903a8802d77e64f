#!/usr/bin/env python3
"""The run time and rate the study's report gives a case (studyReport.py,
cost()) for a run resumed once: two logs in the form colloidDEMFoam
writes, the first part kept by Allrun -resume as
log.colloidDEMFoam.to6e-05 (earlier 'Timing' and 'ExecutionTime' lines
superseded by its last ones), the second as log.colloidDEMFoam.

  part 1: to 60 us, ExecutionTime 125 s, DEM 100 s + coupling 20 s at
          1.0e7 particle-steps/s per rank
  part 2: to 110 us, ExecutionTime 62 s, DEM 50 s + coupling 10 s at
          2.0e7 particle-steps/s per rank

Expected (by hand): end 110 us, run time 125 + 62 = 187 s, rate
(1e7 x 120 + 2e7 x 60)/180 = 1.3333e7 per rank (to 1e-12 relative).

usage: testStudyCost.py colloidFoamDir workDir"""
import os
import shutil
import sys


def part(path, times, timing, seconds):
    with open(path, "w") as f:
        for t in times:
            f.write("Time = %g\n\nProgress: ...\n" % t)
        for dem, coupling, rate in timing:
            f.write("Timing (master, wall clock): DEM %g s, coupling %g s; %g particle-steps "
                    "per second per rank\n" % (dem, coupling, rate))
        for s in seconds:
            f.write("ExecutionTime = %g s  ClockTime = %d s\n\n" % (s, s + 1))
        f.write("End\n")


def main():
    root, work = sys.argv[1:3]
    sys.path.insert(0, os.path.join(root, "src", "python"))
    sys.path.insert(0, os.path.join(root, "tutorials", "slotCoater"))
    import studyReport

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    part(os.path.join(work, "log.colloidDEMFoam.to6e-05"), [5e-5, 6e-5],
         [(50, 10, 0.9e7), (100, 20, 1e7)], [60, 125])
    part(os.path.join(work, "log.colloidDEMFoam"), [1e-4, 1.1e-4],
         [(50, 10, 2e7)], [62])
    end, seconds, rate = studyReport.cost(work)
    expected = (1.1e-4, 187.0, (1e7*120 + 2e7*60)/180)
    ok = all(abs(a - b) <= 1e-12*abs(b) for a, b in zip((end, seconds, rate), expected))
    print("end %g s, run time %g s, %g particle-steps/s per rank (expected %g, %g, %g): %s"
          % (end, seconds, rate, *expected, "ok" if ok else "FAIL"))

    # a run in one part: its own figures
    os.remove(os.path.join(work, "log.colloidDEMFoam.to6e-05"))
    one = studyReport.cost(work)
    good = all(abs(a - b) <= 1e-12*abs(b) for a, b in zip(one, (1.1e-4, 62.0, 2e7)))
    print("one part: %s: %s" % (one, "ok" if good else "FAIL"))
    ok = ok and good
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
