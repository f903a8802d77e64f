#!/usr/bin/env python3
"""Quantities of interest of the settling error studies, with their closed
forms: the velocity at the last write time t of a particle released at
rest (Stokes drag, gravity, buoyancy), in quiescent liquid or, where the
case has system/poiseuille (H, Umax [m, m/s]), in the plane Poiseuille flow
U_x(y) = 4 Umax y (H - y)/H^2 that setPoiseuilleU.py prescribes:
    velocity   v_y(t) = -v_s (1 - exp(-t/tau)),
    velocityX  v_x(t) = U_x(y_p) (1 - exp(-t/tau))   (Poiseuille only),
    tau = rho_p d^2/(18 mu),  v_s = (rho_p - rho_f) g d^2/(18 mu).
(The displacement, 4e-14 m by then, is not used: the written positions
resolve it to 3 digits only.)  Prints 'name value closedForm' lines
(colloidErrorStudy).  Run in the case."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["COLLOIDFOAM_DIR"], "src", "python"))
import foamDict  # noqa: E402
import particleCloud  # noqa: E402

props = foamDict.read("constant/couplingProperties")
rho_f, mu = props["fluid"]["rho"], props["fluid"]["mu"]
d, rho_p = props["particles"]["diameter"], props["particles"]["density"]
g = -foamDict.read("constant/g")["value"][1]
tau = rho_p*d**2/(18*mu)
vs = (rho_p - rho_f)*g*d**2/(18*mu)

times = particleCloud.write_times(".")
last = particleCloud.read(times[-1])
t = particleCloud.time(times[-1]) - particleCloud.time(times[0])
if len(last["position"]) != 1 or t <= 0:
    sys.exit("settlingQuantities: expected one particle at two write times")
growth = 1 - math.exp(-t/tau)
print("velocity %.15g %.15g" % (last["velocity"][0][1], -vs*growth))
if os.path.exists("system/poiseuille"):
    flow = foamDict.read("system/poiseuille")
    H, Umax, y = flow["H"], flow["Umax"], last["position"][0][1]
    print("velocityX %.15g %.15g" % (last["velocity"][0][0], 4*Umax*y*(H - y)/H**2*growth))
