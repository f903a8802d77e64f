#!/usr/bin/env python3
"""Quantities of interest of one rung of benchmarks/approachErrorStudy:
two of the slot coater's spheres (d = 0.3 um, glass, A = 0.43e-20 J, at
the isoelectric point: van der Waals and lubrication, no double layer)
closing in quiescent water from a gap of 20 nm.  Reads the gap the DEM
printed every step (gap.dat: step, gap [um]) and the DEM step
(constant/couplingProperties), and prints, for colloidErrorStudy,

    timeTo5nm   time from the start until the gap first falls to 5 nm [s]
    time5to1nm  time from 5 nm to 1 nm (the lubrication's inner cut-off)
                [s], the stiff last stage

each by linear interpolation between the two steps around the crossing.
With -closedForm it prints instead the overdamped approach times of the
same force laws (Stokes drag of each sphere and pair lubrication against
the van der Waals attraction, each shifted or faded at its outer cut-off,
Simpson's rule): the DEM's inertia
(relaxation time 12.5 ns against stages of 24 us and more) makes them
differ by about 1e-3.

usage: approachQuantities.py [-closedForm]"""
import math
import re
import sys

def couplingEntry(name):
    text = open("constant/couplingProperties").read()
    m = re.search(r"\b%s\s+([^;\s]+)\s*;" % name, text)
    if not m:
        raise SystemExit("constant/couplingProperties: no %s" % name)
    return float(m.group(1))


def parameter(name):
    """An entry of system/approachParameters (SI units)"""
    text = open("system/approachParameters").read()
    m = re.search(r"^%s\s+([^;\s]+)\s*;" % name, text, re.M)
    if not m:
        raise SystemExit("system/approachParameters: no %s" % name)
    return float(m.group(1))


# The case's physics, from where the run takes it (SI units)
HAMAKER = parameter("hamaker")
VDW_CUTOFF = parameter("vdwOuterCutoff")
LUB_CUTOFF = parameter("lubricationOuterCutoff")
LUB_FADE = parameter("lubricationFade") == 1
VDW_FADE = parameter("vdwFade") == 1
START = parameter("initialGap")
RADIUS = 0.5*couplingEntry("diameter")
MU = couplingEntry("mu")


def crossings(levels):
    """Times [s] when the gap first falls to each level [m]"""
    dt = couplingEntry("timeStep")
    times = {}
    previous = None
    for line in open("gap.dat"):
        fields = line.split()
        if len(fields) != 2 or not fields[0].isdigit():
            continue
        step, gap = int(fields[0]), float(fields[1])*1e-6
        if previous is not None:
            for level in levels:
                if level not in times and previous[1] > level >= gap:
                    f = (previous[1] - level)/(previous[1] - gap)
                    times[level] = (previous[0] + f*(step - previous[0]))*dt
        previous = (step, gap)
    missing = [l for l in levels if l not in times]
    if missing:
        raise SystemExit("gap.dat: the gap never fell to %s m (last %s m): run longer"
                         % (missing, previous[1] if previous else None))
    return times


def smoothStep(h, cutoff):
    """The faded form's weight: 1 up to half the cut-off, 0 at it"""
    y = min(1.0, max(0.0, (cutoff - h)/(0.5*cutoff)))
    return 3*y*y - 2*y*y*y


def lubricationShape(h):
    """The lubrication's 1/h with its outer cut-off [1/m] (lubrication.H:
    shifted, or faded)"""
    if h >= LUB_CUTOFF:
        return 0.0
    if LUB_FADE:
        return smoothStep(h, LUB_CUTOFF)/h
    return 1/h - 1/LUB_CUTOFF


def attractionShape(h):
    """The van der Waals 1/h^2 with its outer cut-off [1/m^2]
    (gapCutoffs.H: shifted, or faded)"""
    if h >= VDW_CUTOFF:
        return 0.0
    if VDW_FADE:
        return smoothStep(h, VDW_CUTOFF)/(h*h)
    return 1/(h*h) - 1/(VDW_CUTOFF*VDW_CUTOFF)


def overdamped(a, b, intervals=200000):
    """Overdamped time [s] for the gap to close from b to a [m]"""
    rs = RADIUS/2      # reduced radius
    stokes = 6*math.pi*MU*RADIUS

    def integrand(h):
        force = HAMAKER*rs/6*attractionShape(h)
        lubrication = 6*math.pi*MU*rs*rs*lubricationShape(h)
        # each sphere: drag K v, and c (v1 - v2) with v2 = -v1
        return (stokes + 2*lubrication)/(2*force)

    dh = (b - a)/intervals
    total = integrand(a) + integrand(b)
    for i in range(1, intervals):
        total += (4 if i % 2 else 2)*integrand(a + i*dh)
    return total*dh/3


def main():
    if sys.argv[1:] == ["-closedForm"]:
        print("timeTo5nm %.10g" % overdamped(5e-9, START))
        print("time5to1nm %.10g" % overdamped(1e-9, 5e-9))
        return
    t = crossings([5e-9, 1e-9])
    print("timeTo5nm %.10g" % t[5e-9])
    print("time5to1nm %.10g" % (t[1e-9] - t[5e-9]))


if __name__ == "__main__":
    main()
