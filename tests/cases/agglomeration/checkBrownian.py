#!/usr/bin/env python3
"""Brownian motion in the coupled solver (runBrownianTest.sh): the mean
square displacement of the free spheres from t = 0 to the last write
against the Langevin closed form for spheres started at rest,

  <r^2> = 6 D [t - tau (3 - 4 exp(-t/tau) + exp(-2 t/tau))/2],
  D = k_B T/(6 pi mu R),  tau = m/(6 pi mu R),

within 4 standard errors of the mean of N (sqrt(2/(3N)) of it, 1.8 % for
2000); with a serial run's folder, every position within 1e-6 of the rms
displacement of that run's (the random forces do not depend on the
ranks).

usage: checkBrownian.py caseDir [serialCaseDir]"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "src", "python"))
import foamDict  # noqa: E402
import particleCloud  # noqa: E402


def main():
    case = sys.argv[1]
    props = foamDict.read(os.path.join(case, "constant", "couplingProperties"))
    mu, d, rho = props["fluid"]["mu"], props["particles"]["diameter"], props["particles"]["density"]
    T = props["brownian"]["temperature"]
    R = d/2
    K = 6*math.pi*mu*R
    m = rho*4.0/3.0*math.pi*R**3
    tau, D = m/K, 1.380649e-23*T/K
    times = particleCloud.write_times(case)
    first, last = particleCloud.read(times[0]), particleCloud.read(times[-1])
    t = particleCloud.time(times[-1]) - particleCloud.time(times[0])
    N = len(first["id"])
    if first["id"] != last["id"]:
        print("FAIL: %d particles at the start, %d at the end" % (N, len(last["id"])))
        return 1
    msd = sum(sum((a - b)**2 for a, b in zip(p1, p0))
              for p0, p1 in zip(first["position"], last["position"]))/N
    ref = 6*D*(t - tau*(3 - 4*math.exp(-t/tau) + math.exp(-2*t/tau))/2)
    err = math.sqrt(2.0/(3*N))
    ok = abs(msd/ref - 1) <= 4*err
    print("N %d, t = %.3g tau: MSD %.6g m^2, Langevin %.6g m^2 (%+.2f %%, standard error %.2f %%)"
          % (N, t/tau, msd, ref, 100*(msd/ref - 1), 100*err))
    if len(sys.argv) > 2:
        serial = particleCloud.read(particleCloud.write_times(sys.argv[2])[-1])
        rms = math.sqrt(msd)
        worst = max(math.sqrt(sum((a - b)**2 for a, b in zip(p, q)))
                    for p, q in zip(serial["position"], last["position"]))
        same = serial["id"] == last["id"] and worst <= 1e-6*rms
        print("largest difference from the serial run: %.3g m (%.3g of the rms displacement)"
              % (worst, worst/rms))
        ok = ok and same
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
