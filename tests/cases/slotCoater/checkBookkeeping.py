#!/usr/bin/env python3
"""Particle bookkeeping of a slot-coater run (tutorials/slotCoater) against
the numbers its settings imply.

1. The run reached END_TIME and wrote the particles at every write.
2. At every write of log.colloidDEMFoam: present (LIGGGHTS' atom count) =
   inserted (counted by the coupling as particles first appear) - removed
   (counted by the DEM's outflow fix), and the write time's cloud
   (lagrangian/particles) holds the particles present less those the
   coupling step located outside the fluid, which must be none (the feed
   places its particles in the fluid).
3. The initial fill (DEM/fill.data) holds, per region (gap and slot),
   solidsFraction x region volume / V_p particles (LIGGGHTS rounds: +-1).
4. inserted = fill + the feed: each insertion k of the log ("Feed: N
   particles", one per feed interval of constant/couplingProperties)
   places floor(k R T) - floor((k - 1) R T) particles, R = solidsFraction
   Q / V_p with Q the inflow the feed reports, itself q span within 1e-8
   (the feed q = webSpeed x wetThickness per unit span; the inlet's
   profile is scaled so that its faces carry q, and the particle run
   reads it as the steady flow wrote it, to 10 digits), T the interval; the number of insertions is that of the intervals
   completed before the last coupling step.
5. Some particles were removed (the check of 2 is not vacuous).

Geometry from DEM/slotCoater.liggghts (written by Allrun, um), particle
diameter from system/slotCoaterParameters.

usage: checkBookkeeping.py CASE END_TIME    (writes CASE/bookkeeping.txt)
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402

LINE = re.compile(r"Particles: present (\d+), inserted (\d+), removed (\d+); written (\d+)")
COUPLING = re.compile(r"Coupling: (\d+) particles, (\d+) outside the fluid")


def liggghtsVariables(path):
    return {m.group(1): float(m.group(2)) for m in
            re.finditer(r"^variable (\w+) equal (\S+)", open(path).read(), re.M)}


def main():
    case, endTime = sys.argv[1], float(sys.argv[2])
    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print("%-72s %s" % (text, "ok" if good else "FAILED"))

    log = open(os.path.join(case, "log.colloidDEMFoam")).read()
    times = [float(t) for t in re.findall(r"^Time = (\S+)", log, re.M)]
    check(bool(times) and abs(times[-1] - endTime) <= 1e-9*endTime,
          "run reached endTime %g s (last time %s)" % (endTime, times[-1] if times else "none"))

    # Each write's counts, with the coupling step's own count of particles
    # outside the fluid (the locator's, not the writer's), which the line
    # before it gives
    counts = []
    located = None
    for line in log.splitlines():
        m = COUPLING.match(line)
        if m:
            located = tuple(int(g) for g in m.groups())
        m = LINE.match(line)
        if m:
            counts.append(tuple(int(g) for g in m.groups()) + (located,))
    files = particleCloud.write_times(case)
    check(len(counts) == len(files) and len(counts) > 2,
          "%d writes, %d particle files" % (len(counts), len(files)))
    for (present, inserted, removed, written, located), path in zip(counts, files):
        nFile = len(particleCloud.read(path)["position"])
        check(present == inserted - removed and located is not None
              and located[0] == present and located[1] == 0
              and nFile == written == present,
              "%-20s present %d = inserted %d - removed %d; read %d = present - %s outside"
              % (os.path.basename(path), present, inserted, removed, nFile,
                 located[1] if located else "?"))
    present, inserted, removed, written, located = counts[-1]

    g = liggghtsVariables(os.path.join(case, "DEM", "slotCoater.liggghts"))
    params = open(os.path.join(case, "system", "slotCoaterParameters")).read()
    d = 1e6*float(re.search(r"^particleDiameter\s+(\S+);", params, re.M).group(1))
    vp = math.pi/6*d**3
    phi = g["solidsFraction"]
    gapVolume = (g["xHi"] - g["xLo"])*g["gap"]*g["span"]
    slotVolume = g["slotWidth"]*(g["yTop"] - g["gap"])*g["span"]
    expectedFill = phi*gapVolume/vp + phi*slotVolume/vp
    fill = int(re.search(r"^(\d+) atoms", open(os.path.join(case, "DEM", "fill.data")).read(),
                         re.M).group(1))
    check(abs(fill - expectedFill) <= 2,
          "initial fill %d, expected %.1f (solids fraction %g)" % (fill, expectedFill, phi))

    props = open(os.path.join(case, "constant", "couplingProperties")).read()
    interval = float(re.search(r"^feed\s*\{[^}]*?^\s*interval\s+(\S+);", props, re.M | re.S).group(1))
    couplingStep = float(re.search(r"^deltaT\s+(\S+);",
                                   open(os.path.join(case, "system", "controlDict")).read(),
                                   re.M).group(1))
    # The inflow the feed found (its start-up line), the feed q span to
    # 1e-8: the particle run's inlet profile is the steady flow's, written
    # with 10 digits; the counts follow from the inflow it has
    inflow = float(re.search(r"^Feed: through patch inlet, inflow (\S+) m\^3/s", log,
                             re.M).group(1))*1e12    # m^3/s to um^3/us
    q = g["webSpeed"]*g["wetThickness"]*g["span"]
    check(abs(inflow - q) <= 1e-8*q, "feed inflow %.10g um^3/us, q span %.10g" % (inflow, q))
    rate = phi*inflow/vp     # per us
    T = interval*1e6        # us
    fed = [int(n) for n in re.findall(r"^Feed: (\d+) particles", log, re.M)]
    nInsertions = int(math.floor((endTime - couplingStep)/interval + 1e-9))
    expectedFeed = [math.floor(k*rate*T) - math.floor((k - 1)*rate*T)
                    for k in range(1, nInsertions + 1)]
    check(fed == expectedFeed,
          "feed: insertions %s, expected %s (%.4g per interval)" % (fed, expectedFeed, rate*T))
    check(inserted - fill == sum(fed),
          "fed %d = the insertions' %d" % (inserted - fill, sum(fed)))
    check(removed > 0, "removed %d particles through the outflows" % removed)

    velocity = particleCloud.read(files[-1])["velocity"]
    mean = [sum(v[k] for v in velocity)/len(velocity) for k in range(3)]
    with open(os.path.join(case, "bookkeeping.txt"), "w") as f:
        f.write("%d %d %d %.10g %.10g %.10g\n" % ((present, inserted, removed) + tuple(mean)))
    print("final mean particle velocity (%.8g %.8g %.8g) m/s" % tuple(mean))
    print("bookkeeping: %s" % ("passed" if ok else "FAILED"))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
