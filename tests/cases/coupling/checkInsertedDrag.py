#!/usr/bin/env python3
"""Particles inserted at rest in DEM step s into plane Poiseuille flow
    U_x(y) = 4 Umax y (H - y) / H^2
with gravity g along -y have the velocity
    v(t) = V (1 - exp(-(t - t_i)/tau)),  V = (U_x(y_p), -v_s, 0),
    tau = rho_p d^2 / (18 mu),   v_s = (rho_p - rho_f) g d^2 / (18 mu),
    t_i = (s - 1/2) dt
if the drag, gravity and buoyancy act on them from step s.  t_i is
velocity Verlet's start for a particle inserted in step s: it gets the
full kick of step s (half at its end, half at the start of step s + 1)
before it first moves, in step s + 1, as one released half a step
earlier would.

Checks, at every write after the insertion, for each inserted particle
(ids above those present at t = 0):
  - v_y within 0.1 % of the closed form (it is exact to about 1e-5;
    starting the clock half a step late is 0.6 % at t - t_i = tau, the
    drag withheld until the next exchange 5 steps later about 7 %);
  - v_x within 1 % (the interpolated U_x, as the settling test);
  - v_z within 1 % of v_s;
and that all n inserted particles are there.

usage: checkInsertedDrag.py caseDir H Umax insertStep nInserted
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))  # particleCloud
import particleCloud  # noqa: E402
from checkSettling import entry, gravityAlongMinusY  # noqa: E402

TOL_Y = 0.001
TOL = 0.01


def main():
    case, H, Umax = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    step, nInserted = int(sys.argv[4]), int(sys.argv[5])
    props = open(case + "/constant/couplingProperties").read()
    rho_f, mu = entry(props, "rho"), entry(props, "mu")
    d, rho_p = entry(props, "diameter"), entry(props, "density")
    dt = entry(props, "timeStep")
    g = gravityAlongMinusY(case)

    tau = rho_p*d**2/(18*mu)
    vs = (rho_p - rho_f)*g*d**2/(18*mu)
    ti = (step - 0.5)*dt
    ok = True
    initial = None
    nChecked = 0

    for path in particleCloud.write_times(case):
        t = particleCloud.time(path)
        data = particleCloud.read(path)
        ids = data["id"]
        if initial is None:
            initial = set(ids)      # the particles of the first write
            continue
        if t <= ti:
            continue
        inserted = [k for k, i in enumerate(ids) if i not in initial]
        if len(inserted) != nInserted:
            print("t = %.4g s: %d inserted particles, expected %d"
                  % (t, len(inserted), nInserted))
            ok = False
            continue
        growth = 1 - math.exp(-(t - ti)/tau)
        worst = [0.0, 0.0, 0.0]
        for k in inserted:
            y = data["position"][k][1]
            v = data["velocity"][k]
            Ux = 4*Umax*y*(H - y)/H**2*growth
            vy = -vs*growth
            err = [abs(v[0] - Ux)/abs(Ux), abs(v[1] - vy)/abs(vy), abs(v[2])/vs]
            worst = [max(a, b) for a, b in zip(worst, err)]
            ok = ok and err[0] < TOL and err[1] < TOL_Y and err[2] < TOL
        nChecked += 1
        print("t - t_i = %.3f tau: largest rel. error of the %d inserted"
              " particles: v_x %.3g %%, v_y %.3g %%, v_z %.3g %% of v_s"
              % ((t - ti)/tau, len(inserted), 100*worst[0], 100*worst[1],
                 100*worst[2]))

    if nChecked == 0:
        print("no write after the insertion")
        ok = False
    print("PASS" if ok else
          "FAIL (tolerance: v_y 0.1 %, v_x and v_z 1 %)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
