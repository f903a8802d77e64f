#!/usr/bin/env python3
"""Quantity of interest of the settling error study, with its closed
form: the vertical velocity at the last write time t of a particle
released at rest in quiescent liquid (Stokes drag, gravity, buoyancy):
    v_y(t) = -v_s (1 - exp(-t/tau)),
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
print("velocity %.15g %.15g" % (last["velocity"][0][1], -vs*(1 - math.exp(-t/tau))))
