#!/usr/bin/env python3
"""Quantities of interest of one rung of benchmarks/reboundErrorStudy: the
wet restitution coefficient e of a glass sphere on a wall at Stokes
numbers 50, 100 and 500 with the plugin's default lubrication (e_St...),
and at 20, 50, 100 and 500 with the film ruptured after contact
(lubricationAfterContact 1: eRuptured_St...).  Read from the tables that
the test programs printed (log.rebound, log.reboundRuptured: St, e DEM,
e ref, ...); each line gives the reference integrated in the test (the
same force laws as a 1-D ODE, RK4 converged to 1e-6) as the closed form.

usage: reboundQuantities.py"""
import re
import sys

WANTED = {"log.rebound": ("e", (50, 100, 500)),
          "log.reboundRuptured": ("eRuptured", (20, 50, 100, 500))}


def table(log):
    """{St: (e DEM, e ref)} of the test's table"""
    rows = {}
    with open(log) as f:
        for line in f:
            m = re.match(r"^\s+([0-9.eE+]+)\s+([-0-9.]+)\s+([-0-9.]+)\s+[-0-9.]+\s+"
                         r"[-0-9.]+\s+[-0-9.]+\s*$", line)
            if m:
                rows[float(m.group(1))] = (float(m.group(2)), float(m.group(3)))
    return rows


def main():
    for log, (prefix, stokes) in WANTED.items():
        rows = table(log)
        for St in stokes:
            if St not in rows:
                sys.exit("reboundQuantities: no St %g in %s" % (St, log))
            dem, ref = rows[St]
            print("%s_St%g %.10g %.10g" % (prefix, St, dem, ref))


if __name__ == "__main__":
    main()
