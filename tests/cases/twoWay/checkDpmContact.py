"""Rebound of two Goldschmidt spheres (and of one on a wall) in LIGGGHTS
against DPMFoam's own force law (PairSpringSliderDashpot /
WallSpringSliderDashpot, OpenFOAM v1912), integrated here:

    m* x'' = -k_N x^(3/2) - alpha sqrt(m* k_N) x^(1/4) x',
    k_N = 4/3 E* sqrt(R*),

from x = 0, x' = v until x returns to 0; the rebound coefficient is
-x'/v there.  Pair: m* = m/2, R* = R/2, E* = E/(2 (1 - nu^2)); wall:
m* = m, R* = R, 1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w.  The values are
read from the DPMFoam tutorial.

    python3 checkDpmContact.py TUTORIAL RESULTS

RESULTS: lines 'RESULT pair|wall v t z1 vz1 z2 vz2' (um, us; um/us =
m/s) from runDpmContactTest.sh.  Passes when every loss 1 - e and contact duration
(from the positions after the collision) is within 0.2 % of the law's."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "benchmarks", "dpmFoamGoldschmidt"))
from goldschmidtSetup import CLOUD, DIAMETER, PAIR, WALL, entry  # noqa: E402

# On the dissipation 1 - e (2.8 % of the velocity for pairs, 1.4 % for
# walls), so that a damping 1 % off fails, and on the contact's duration
TOLERANCE = 0.002


def collision(m, R, E, alpha, v):
    """Rebound coefficient -x'/v at the end of the contact and the
    contact's duration [s], RK4 with 20 000 steps per Hertz contact time"""
    k = 4.0/3.0*E*math.sqrt(R)
    c = alpha*math.sqrt(m*k)

    def acc(x, u):
        xp = max(x, 0.0)
        return -(k*xp**1.5 + c*xp**0.25*u)/m

    tc = 2.87*(m*m/(R*E*E*v))**0.2
    h = tc/20000.0
    x, u, t = 0.0, v, 0.0
    while True:
        k1x, k1u = u, acc(x, u)
        k2x, k2u = u + 0.5*h*k1u, acc(x + 0.5*h*k1x, u + 0.5*h*k1u)
        k3x, k3u = u + 0.5*h*k2u, acc(x + 0.5*h*k2x, u + 0.5*h*k2u)
        k4x, k4u = u + h*k3u, acc(x + h*k3x, u + h*k3u)
        xn = x + h/6.0*(k1x + 2*k2x + 2*k3x + k4x)
        un = u + h/6.0*(k1u + 2*k2u + 2*k3u + k4u)
        if xn < 0.0:
            # end of contact: interpolate to x = 0
            f = x/(x - xn)
            return -(u + (un - u)*f)/v, t + f*h
        x, u, t = xn, un, t + h


def main():
    tutorial, results = sys.argv[1:3]
    cloud = os.path.join(tutorial, CLOUD)

    def value(key):
        return float(entry(cloud, key))

    E = value("constantProperties/youngsModulus")
    nu = value("constantProperties/poissonsRatio")
    rho = value("constantProperties/rho0")
    d = value(DIAMETER)
    E_w, nu_w = value(WALL + "youngsModulus"), value(WALL + "poissonsRatio")
    m = rho*math.pi/6.0*d**3
    R = 0.5*d
    law = {
        "pair": lambda v: collision(0.5*m, 0.5*R, E/(2.0*(1.0 - nu*nu)), value(PAIR + "alpha"), v),
        "wall": lambda v: collision(m, R, 1.0/((1.0 - nu*nu)/E + (1.0 - nu_w*nu_w)/E_w), value(WALL + "alpha"), v),
    }
    failed = 0
    lines = [l.split() for l in open(results) if l.startswith("RESULT")]
    if len(lines) != 6:
        sys.exit("checkDpmContact: %d results, expected 6" % len(lines))
    r_um = 0.5e6*d
    for _, target, v, t_end, z1, vz1, z2, vz2 in lines:
        v, t_end, z1, vz1, z2, vz2 = (float(a) for a in (v, t_end, z1, vz1, z2, vz2))
        # um, us: free flight to the contact, the contact, free flight
        # apart at the rebound velocity
        if target == "pair":
            e_dem = (vz2 - vz1)/v
            t_dem = t_end - 100.0/v - (z2 - z1 - 2*r_um)/(vz2 - vz1)
        else:
            e_dem = vz1/v
            t_dem = t_end - 50.0/v - (z1 - r_um)/vz1
        e_law, t_law = law[target](v)
        t_law *= 1e6
        loss = (1.0 - e_dem)/(1.0 - e_law) - 1.0
        ok = abs(loss) <= TOLERANCE and abs(t_dem/t_law - 1.0) <= TOLERANCE
        failed += not ok
        print("%s at %g m/s: rebound %.6f, DPMFoam's law %.6f (1 - e %+.3f %%); contact %.3f us, law %.3f us (%+.3f %%) %s"
              % (target, v, e_dem, e_law, 100*loss, t_dem, t_law, 100*(t_dem/t_law - 1),
                 "ok" if ok else "FAILED"))
    sys.exit(1 if failed else 0)


main()
