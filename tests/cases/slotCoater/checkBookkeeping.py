#!/usr/bin/env python3
"""Particle bookkeeping of a slot-coater run (tutorials/slotCoater) against
the numbers its settings imply.

1. The run reached END_TIME and wrote the particles at every write.
2. At every write of log.colloidDEMFoam: present (LIGGGHTS' atom count) =
   inserted (counted by the coupling as particles first appear) - removed
   (counted by the DEM's outflow fix), and the write time's cloud
   (lagrangian/particles) holds the particles present less those the
   coupling step located outside the fluid (the feed zone above the
   inlet).
3. The initial fill (DEM/fill.data) holds, per region (gap and slot),
   solidsFraction x region volume / V_p particles (LIGGGHTS rounds: +-1).
4. inserted = fill + the feed: the feed zone (two diameters above the
   inlet, slotWidth x span) is filled at the solids fraction each time its
   content has moved through the inlet at the feed velocity
   webSpeed x wetThickness / slotWidth; +-1 per batch (rounding).
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
    # outside the fluid (the locator's, not the writer's: the feed zone
    # above the inlet), which the line before it gives
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
              and located[0] == present and nFile == written == present - located[1],
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

    feedZone = g["feedZone"]    # [um], as Allrun wrote it for the DEM
    feedVelocity = g["webSpeed"]*g["wetThickness"]/g["slotWidth"]
    batch = phi*g["slotWidth"]*g["span"]*feedZone/vp
    nBatches = 1 + int(1e-6*endTime*1e6/(feedZone/feedVelocity))   # um/(um/us) = us
    expectedFeed = batch*nBatches
    check(abs(inserted - fill - expectedFeed) <= nBatches,
          "fed %d, expected %d batch(es) of %.2f" % (inserted - fill, nBatches, batch))
    check(removed > 0, "removed %d particles through the outlet" % removed)

    velocity = particleCloud.read(files[-1])["velocity"]
    mean = [sum(v[k] for v in velocity)/len(velocity) for k in range(3)]
    with open(os.path.join(case, "bookkeeping.txt"), "w") as f:
        f.write("%d %d %d %.10g %.10g %.10g\n" % ((present, inserted, removed) + tuple(mean)))
    print("final mean particle velocity (%.8g %.8g %.8g) m/s" % tuple(mean))
    print("bookkeeping: %s" % ("passed" if ok else "FAILED"))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
