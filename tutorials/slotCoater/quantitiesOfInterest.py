#!/usr/bin/env python3
"""The slot coater's quantities of interest, for colloidErrorStudy
(system/errorStudyDict) and for a look after any run: printed as
'name value' lines, SI units.

  touchingParticleFraction  fraction of the particles in the fluid that
                            touch another particle (the coupling's flag:
                            within its touch tolerance), at the last write
  touchingWallFraction      the same for a wall (die, upstream wall,
                            substrate)
  meanContacts              mean number of contacts per particle, there
  leftThroughOutlet         particles removed at the outflow plane by the
                            end (log.colloidDEMFoam; not those removed at
                            the inlet)
  meanVelocityUnderLip      mean x-velocity [m/s] of the particles under the
                            downstream lip (slotWidth < x < slotWidth +
                            downstreamLip, in the gap), averaged over the
                            write times after the start
  contactsFormedPerUs       particle-particle contacts formed per us over
                            the run (postProcessing/contactAnalysis)
  meanContactDuration       mean duration [s] of the particle-particle
                            contacts that ended (0 if none did)

Run in the case folder, after a run (serial or reconstructed parallel)."""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["COLLOIDFOAM_DIR"], "src", "python"))
import contactAnalysis  # noqa: E402
import foamDict  # noqa: E402
import particleCloud  # noqa: E402

params = foamDict.read("system/slotCoaterParameters")
xLo, xHi = params["slotWidth"], params["slotWidth"] + params["downstreamLip"]
gap = params["gap"]

times = [t for t in particleCloud.write_times(".") if particleCloud.time(t) > 0]
if not times:
    sys.exit("quantitiesOfInterest: no write time after the start")
last = particleCloud.read(times[-1])
n = len(last["id"])
if n == 0:
    sys.exit("quantitiesOfInterest: no particles at %s" % times[-1])
print("touchingParticleFraction %.12g" % (sum(last["touchingParticle"])/n))
print("touchingWallFraction %.12g" % (sum(last["touchingWall"])/n))
print("meanContacts %.12g" % (sum(last["nContacts"])/n))

# The outlet's count: the DEM script's fix 'outflow' (its inlet fix,
# 'inletBackflow', counts the particles that left back up the inlet); a
# log from before the per-fix line (2026-12-05), when the outlet was the
# only outflow: the total
removed = None
total = None
with open("log.colloidDEMFoam", errors="replace") as log:
    for line in log:
        m = re.match(r"^Removed per outflow fix:(?:.*,)? outflow (\d+)", line)
        if m:
            removed = int(m.group(1))
        m = re.match(r"^Particles: present \d+, inserted \d+, removed (\d+)", line)
        if m:
            total = int(m.group(1))
if removed is None:
    removed = total
if removed is None:
    sys.exit("quantitiesOfInterest: no 'Removed per outflow fix: ... outflow N'"
             " or 'Particles: ... removed N' line in log.colloidDEMFoam")
print("leftThroughOutlet %d" % removed)

means = []
for t in times:
    p = particleCloud.read(t)
    u = [v[0] for x, v in zip(p["position"], p["velocity"])
         if xLo < x[0] < xHi and x[1] < gap]
    if u:
        means.append(sum(u)/len(u))
if not means:
    sys.exit("quantitiesOfInterest: no particle under the downstream lip at any write time")
print("meanVelocityUnderLip %.12g" % (sum(means)/len(means)))

contacts = contactAnalysis.summary(".")
print("contactsFormedPerUs %.12g" % contacts["pairFormedPerUs"])
print("meanContactDuration %.12g" % contacts["meanPairDuration"])
