#!/usr/bin/env python3
"""A particle released at rest in plane Poiseuille flow
    U_x(y) = 4 Umax y (H - y) / H^2
with gravity g along -y has the velocity
    v(t) = V (1 - exp(-t/tau)),  V = (U_x(y_p), -v_s, 0),
    tau = rho_p d^2 / (18 mu),   v_s = (rho_p - rho_f) g d^2 / (18 mu)
(Stokes drag, gravity, buoyancy; U_x(y_p) barely changes as the particle
settles by v_s t << H).  tau checks the drag coefficient against the
particle mass, v_s against gravity and buoyancy, U_x the interpolation.

Every particle file at t > 0 is checked, each component within 1 %
(relative; z within 1 % of v_s); the last one, after > 11 tau, is the
terminal velocity (transient left < 2e-5).  Properties are read from the
case.

usage: checkSettling.py caseDir H Umax
"""
import math
import re
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402

TOL = 0.01


def entry(text, key):
    m = re.search(r"\b%s\s+([-+0-9.eE]+)\s*;" % key, text)
    if not m:
        sys.exit("checkSettling: no '%s' in couplingProperties" % key)
    return float(m.group(1))


def gravityAlongMinusY(case):
    """|g| of the case's constant/g [m/s^2]; stops unless it points along -y"""
    gvec = [float(v) for v in
            re.search(r"value\s*\(([^)]*)\)", open(case + "/constant/g").read()).group(1).split()]
    g = math.sqrt(sum(c*c for c in gvec))
    if abs(gvec[1] + g) > 1e-12*g:
        sys.exit("%s: expects gravity along -y" % os.path.basename(sys.argv[0]))
    return g


def main():
    case, H, Umax = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    props = open(case + "/constant/couplingProperties").read()
    rho_f, mu = entry(props, "rho"), entry(props, "mu")
    d, rho_p = entry(props, "diameter"), entry(props, "density")
    g = gravityAlongMinusY(case)

    tau = rho_p*d**2/(18*mu)
    vs = (rho_p - rho_f)*g*d**2/(18*mu)
    ok = True

    for path in particleCloud.write_times(case):
        t = particleCloud.time(path)
        if t <= 0:
            continue
        data = particleCloud.read(path)
        if len(data["position"]) != 1:
            sys.exit("checkSettling: expected 1 particle, found %d" % len(data["position"]))
        y = data["position"][0][1]
        v = data["velocity"][0]

        growth = 1 - math.exp(-t/tau)
        Ux = 4*Umax*y*(H - y)/H**2*growth
        vy = -vs*growth
        errX = abs(v[0] - Ux)/abs(Ux)
        errY = abs(v[1] - vy)/abs(vy)
        errZ = abs(v[2])/vs

        print("t = %.4g s = %.3f tau, y_p = %.6g m" % (t, t/tau, y))
        print("    v_x = %.8g m/s, reference %.8g m/s, rel. error %.3g %%" % (v[0], Ux, 100*errX))
        print("    v_y = %.8g m/s, reference %.8g m/s, rel. error %.3g %%" % (v[1], vy, 100*errY))
        print("    v_z = %.3g m/s (%.3g %% of v_s)" % (v[2], 100*errZ))
        ok = ok and errX < TOL and errY < TOL and errZ < TOL

    print("PASS" if ok else "FAIL (tolerance 1 %)")
    return 0 if ok else 1

if __name__ == "__main__":
    sys.exit(main())
