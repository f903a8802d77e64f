#!/usr/bin/env python3
"""The run time and rate the study's report gives a case (studyReport.py,
cost()) for a run resumed three times: logs in the form colloidDEMFoam
writes, the earlier parts kept as Allrun -resume names them (the second
resume from 60 us, after a part that stopped before its first write:
.to6e-05.2), earlier 'Timing' and 'ExecutionTime' lines of a part
superseded by its last ones:

  log.colloidDEMFoam.to6e-05      to 60 us: ClockTime 130 s, DEM 100 s +
                                  coupling 20 s at 1.0e7 particle-steps/s
  log.colloidDEMFoam.to6e-05.2    stopped: ClockTime 5 s, DEM 3 s +
                                  coupling 1 s at 0.5e7
  log.colloidDEMFoam.to0.0001     to 100 us: ClockTime 70 s, DEM 50 s +
                                  coupling 10 s at 2.0e7 (sorts before
                                  6e-05 as a string: the order is by time)
  log.colloidDEMFoam              to 110 us: ClockTime 20 s, DEM 15 s +
                                  coupling 3 s at 3.0e7
  log.colloidDEMFoam.to6e-05~     an editor's backup: not a part

Expected (by hand): the parts in time order, the backup left out; end
110 us (the last part's), wall-clock run time
130 + 5 + 70 + 20 = 225 s ('ClockTime': 'ExecutionTime' is the CPU
time), rate (1e7 x 120 + 0.5e7 x 4 + 2e7 x 60 + 3e7 x 18)/202 per rank
(to 1e-12 relative).

usage: testStudyCost.py colloidFoamDir workDir"""
import os
import shutil
import sys


def part(path, times, timing, clock):
    with open(path, "w") as f:
        for t in times:
            f.write("Time = %g\n\nProgress: ...\n" % t)
        for dem, coupling, rate in timing:
            f.write("Timing (master, wall clock): DEM %g s, coupling %g s; %g particle-steps "
                    "per second per rank\n" % (dem, coupling, rate))
        for s in clock:
            # CPU time below the wall clock, as on a busy machine
            f.write("ExecutionTime = %g s  ClockTime = %d s\n\n" % (0.7*s, s))
        f.write("End\n")


def main():
    root, work = sys.argv[1:3]
    sys.path.insert(0, os.path.join(root, "src", "python"))
    sys.path.insert(0, os.path.join(root, "tutorials", "slotCoater"))
    import studyReport

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    log = os.path.join(work, "log.colloidDEMFoam")
    part(log + ".to6e-05", [5e-5, 6e-5], [(50, 10, 0.9e7), (100, 20, 1e7)], [60, 130])
    part(log + ".to6e-05.2", [6.1e-5], [(3, 1, 0.5e7)], [5])
    part(log + ".to0.0001", [1e-4], [(50, 10, 2e7)], [70])
    part(log, [1.05e-4, 1.1e-4], [(15, 3, 3e7)], [20])
    part(log + ".to6e-05~", [2e-4], [(1, 1, 1e9)], [1000])
    order = [os.path.basename(f) for f in studyReport.run_logs(work)]
    expect_order = ["log.colloidDEMFoam.to6e-05", "log.colloidDEMFoam.to6e-05.2",
                    "log.colloidDEMFoam.to0.0001", "log.colloidDEMFoam"]
    ok = order == expect_order
    print("parts in order: %s: %s" % (order, "ok" if ok else "FAIL (expected %s)" % expect_order))
    end, seconds, rate = studyReport.cost(work)
    expected = (1.1e-4, 225.0, (1e7*120 + 0.5e7*4 + 2e7*60 + 3e7*18)/202)
    good = all(abs(a - b) <= 1e-12*abs(b) for a, b in zip((end, seconds, rate), expected))
    print("end %g s, run time %g s, %.6g particle-steps/s per rank (expected %g, %g, %.6g): %s"
          % (end, seconds, rate, *expected, "ok" if good else "FAIL"))
    ok = ok and good

    # a run in one part: its own figures
    for f in os.listdir(work):
        if f != "log.colloidDEMFoam":
            os.remove(os.path.join(work, f))
    one = studyReport.cost(work)
    good = all(abs(a - b) <= 1e-12*abs(b) for a, b in zip(one, (1.1e-4, 20.0, 3e7)))
    print("one part: %s: %s" % (one, "ok" if good else "FAIL"))
    ok = ok and good
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
