#!/usr/bin/env python3
"""Contacts formed in simple shear (runShearTest.sh) against
Smoluchowski's rectilinear kernel: spheres of radius R following the
shear U_x = G y collide with those whose centres pass within 2R, at the
rate (4/3) G (2R)^3 n^2/2 per unit volume in an unbounded suspension.  In
the band of thickness W that holds the centres, a sphere near the band's
edge has partners on one side only; integrated over the band,

  rate = (n^2/2) Lx Lz G  int_0^W dy  int dh |h| 2 sqrt(4R^2 - h^2),

the inner integral over the offsets h in [-2R, 2R] with y + h in the band
(W -> infinity gives the unbounded kernel).  n = N/(Lx W Lz) from the
particles at t = 0.  The count of collisions is Poisson distributed:
asserted within 3 standard deviations, sqrt(expected).

usage: checkShearCollisions.py caseDir"""
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "src", "python"))
import foamDict  # noqa: E402


def band_integral(W, R, steps=4000):
    """int_0^W dy int_{max(-2R,-y)}^{min(2R,W-y)} |h| 2 sqrt(4R^2 - h^2) dh"""
    a = 2*R

    def F(h):   # antiderivative of h 2 sqrt(a^2 - h^2) for h >= 0, from 0
        return (2.0/3.0)*(a**3 - (a*a - h*h)**1.5)

    def inner(y):
        lo, hi = max(-a, -y), min(a, W - y)
        return F(hi) + F(-lo)   # |h| symmetric: both sides from 0
    dy = W/steps
    return sum(inner((k + 0.5)*dy) for k in range(steps))*dy


def main():
    case = sys.argv[1]
    s = foamDict.read(os.path.join(case, "system", "shear"))
    G, R, W = s["G"], s["R"], s["y1"] - s["y0"]
    Lx, Lz = s["Lx"], s["Lz"]
    files = glob.glob(os.path.join(case, "postProcessing", "contactAnalysis", "*", "contacts.csv"))
    rows = list(csv.DictReader(l for l in open(files[0]) if not l.startswith("#")))
    N = int(rows[0]["particles"])
    T = float(rows[-1]["time"]) - float(rows[0]["time"])
    formed = sum(int(r["pairFormed"]) for r in rows[1:])
    n = N/(Lx*W*Lz)
    unbounded = (4.0/3.0)*G*(2*R)**3*n*n/2*(Lx*W*Lz)
    rate = n*n/2*Lx*Lz*G*band_integral(W, R)
    expected = rate*T
    sigma = math.sqrt(expected)
    ok = abs(formed - expected) <= 3*sigma and int(rows[0]["pairContacts"]) == 0
    print("particles %d, n = %.4g 1/m^3, strain G T = %.3g" % (N, n, G*T))
    print("rate: unbounded kernel %.4g 1/s, in the band %.4g 1/s" % (unbounded, rate))
    print("contacts formed %d, expected %.1f +- %.1f (Poisson): ratio %.3f, %.2f sigma"
          % (formed, expected, sigma, formed/expected, (formed - expected)/sigma))
    print("contacts at the start: %s" % rows[0]["pairContacts"])
    print("PASS" if ok else "FAIL (3 standard deviations)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
