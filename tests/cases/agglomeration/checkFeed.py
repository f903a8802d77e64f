#!/usr/bin/env python3
"""The coupling's feed in the channel of runFeedTest.sh (plane Poiseuille
flow u(y) = 4 U_max y (H - y)/H^2 along x, or plug flow u = U_max with
the walls moving along; inlet x = 0, walls y = 0 and H, periodic in z
over L_z), against closed forms:

  - counts: insertion k (every T = 1 us; 29 of them in 30 us) places
    floor(k R T) - floor((k - 1) R T) particles, R = phi Q/V_p, Q the
    inlet's discrete inflow (the profile at its 20 x 5 face centres, the
    face values of the zero-gradient inlet): every insertion exact, and
    the particles present at the end are all of them and the channel's
    own (id 1, far from the inlet; not counted below);
  - flux profile: the particles' y in ten bins of 10 um against the
    fractions of the inflow through them (integral of u over the bin, the
    band within r + minimumGap of the walls left out): chi-square below
    27.9 (9 degrees of freedom, p = 0.001); particles fed uniformly over
    the Poiseuille inlet instead of with the flux put 3.4x too many in the
    bins at the walls;
  - within the faces: the particles' z within their face (10 um) in four
    bins, uniform: chi-square below 16.3 (3 degrees of freedom, p =
    0.001; a face's two triangles not both drawn fails it);
  - swept region: a particle placed at insertion k at depth s, uniform up
    to u T, reaches x = s + u (t_end - k T) by the end, so that its entry
    time t_end - x/u (u its own velocity at the end) is uniform on (0,
    29 T]: Kolmogorov-Smirnov distance below 1.95/sqrt(n) (p = 0.001),
    and every one within it (to 0.05 T, the change of a particle's
    velocity along its path): a particle placed deeper than its
    liquid swept (e.g. at a depth drawn without its velocity) enters
    "before the start"; and within its own interval (k from its id and
    the insertions' counts) the phase (k T - t_entry)/T = s/(u T) uniform
    on (0, 1): Kolmogorov-Smirnov as above (all at depth 0 or u T/2
    fails it);
  - gaps: the solver's "Inserted particles" of every insertion that
    placed some: a smallest gap of at least minimumGap less what the shear
    (at most 4 U_max/H) can close in the coupling step before the solver
    measures it (4.4e-11 m), or none closer than a radius (0.5 um) (0.1 um; the start-up overlap check,
    periodic images included), and at the end no centre closer than r +
    minimumGap to a wall.

With two cases (serial, parallel): the same particles, ids and positions
within 1e-10 m.

usage: checkFeed.py case poiseuille|plug  |  checkFeed.py case otherCase"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "src", "python"))
import particleCloud  # noqa: E402

H, LZ, UMAX = 100e-6, 50e-6, 0.05     # [m], [m], [m/s]: runFeedTest.sh
NY, NZ = 20, 5                        # inlet faces (blockMeshDict)
PHI, GAP, T, END = 0.05, 1e-7, 1e-6, 3e-5
D = 1e-6                              # particle diameter [m]

ok = True


def check(condition, text):
    global ok
    print("%s: %s" % ("ok  " if condition else "FAIL", text))
    ok = ok and condition


PROFILE = "poiseuille"


def u(y):
    return 4*UMAX*y*(H - y)/H**2 if PROFILE == "poiseuille" else UMAX


def ks_uniform(values, lo, hi):
    """Kolmogorov-Smirnov distance of values to the uniform on (lo, hi)"""
    v = sorted((x - lo)/(hi - lo) for x in values)
    n = len(v)
    return max(max((i + 1)/n - x, x - i/n) for i, x in enumerate(v))


def compare(a, b):
    pa = particleCloud.read(particleCloud.latest(a))
    pb = particleCloud.read(particleCloud.latest(b))
    check(pa["id"] == pb["id"], "the same %d ids (other run: %d)" % (len(pa["id"]), len(pb["id"])))
    worst = max((max(abs(p - q) for p, q in zip(xa, xb))
                 for xa, xb in zip(pa["position"], pb["position"])), default=0)
    check(pa["id"] == pb["id"] and worst <= 1e-10,
          "positions agree within %.3g m (allowed 1e-10 m)" % worst)


def main():
    global PROFILE
    if sys.argv[2] not in ("poiseuille", "plug"):
        compare(sys.argv[1], sys.argv[2])
        sys.exit(0 if ok else 1)
    case, PROFILE = sys.argv[1], sys.argv[2]
    log = open(os.path.join(case, "log.colloidDEMFoam")).read()

    # Counts against the closed form of the discrete inflow
    dy, dz = H/NY, LZ/NZ
    Q = sum(u((j + 0.5)*dy)*dy*dz for j in range(NY))*NZ
    vp = math.pi/6*D**3
    R = PHI*Q/vp
    counts = [int(n) for n in re.findall(r"^Feed: (\d+) particles", log, re.M)]
    expected = [math.floor(k*R*T) - math.floor((k - 1)*R*T) for k in range(1, len(counts) + 1)]
    check(len(counts) == 29, "%d insertions in %g s (expected 29)" % (len(counts), END))
    check(counts == expected, "every insertion's count: %s ... (expected %s ..., R T = %.4f)"
          % (counts[:4], expected[:4], R*T))
    every = particleCloud.read(particleCloud.latest(case))
    check(len(every["id"]) == 1 + sum(counts) and every["id"][0] == 1,
          "%d particles at the end: the channel's own (id 1) and the %d placed"
          % (len(every["id"]), sum(counts)))
    fed = [k for k, i in enumerate(every["id"]) if i > 1]
    p = {key: [every[key][k] for k in fed] for key in every}
    n = len(fed)

    # Flux profile, without the bands at the walls
    def flux(a, b):    # integral of u over (a, b) within the allowed band
        a, b = max(a, D/2 + GAP), min(b, H - D/2 - GAP)
        if PROFILE == "plug":
            F = lambda y: UMAX*y
        else:
            F = lambda y: 4*UMAX*(H*y**2/2 - y**3/3)/H**2
        return F(b) - F(a)
    bins = [0]*10
    for x in p["position"]:
        bins[min(int(x[1]/(H/10)), 9)] += 1
    chi2 = 0
    for j, count in enumerate(bins):
        e = n*flux(j*H/10, (j + 1)*H/10)/flux(0, H)
        chi2 += (count - e)**2/e
    check(chi2 < 27.9, "particles per 10 um of y %s: chi-square %.2f against the flux"
          " profile (allowed < 27.9)" % (bins, chi2))

    # Within the faces (10 um in z)
    fz = [0]*4
    for x in p["position"]:
        fz[min(int(4*(x[2] % (LZ/NZ))/(LZ/NZ)), 3)] += 1
    chi2z = sum((c - n/4)**2/(n/4) for c in fz)
    check(chi2z < 16.3, "z within the faces in quarters %s: chi-square %.2f against"
          " uniform (allowed < 16.3)" % (fz, chi2z))

    # Entry times uniform on (0, 29 T], and within each interval
    span = 29*T
    entry = [END - x[0]/v[0] for x, v in zip(p["position"], p["velocity"])]
    te = sorted(entry)
    ks = ks_uniform(te, 0, span)
    check(ks < 1.95/math.sqrt(n), "entry times: Kolmogorov-Smirnov distance %.4f to"
          " uniform on (0, %g] (allowed < %.4f)" % (ks, span, 1.95/math.sqrt(n)))
    # (the velocity at the end stands for that along the path: the
    # interpolated velocity in the inlet's cells changes along x by a few
    # per mille, which over up to 29 intervals shifts an entry time by up
    # to 0.03 T: measured 0.025 T)
    check(te[0] > -0.05*T and te[-1] <= span + 0.05*T,
          "entry times from %.4g to %.4g s, within (0, %g] (+-0.05 T)" % (te[0], te[-1], span))
    first = [2]      # the first id of each insertion (id 1: the channel's)
    for c in counts:
        first.append(first[-1] + c)
    phase = []
    for i, t_in in zip(p["id"], entry):
        k = max(j for j in range(len(counts)) if first[j] <= i) + 1
        phase.append((k*T - t_in)/T)
    ksPhase = ks_uniform(phase, 0, 1)
    check(ksPhase < 1.95/math.sqrt(n) and -0.05 < min(phase) and max(phase) < 1.05,
          "phase within its interval from %.3f to %.3f: Kolmogorov-Smirnov distance %.4f"
          " to uniform on (0, 1) (allowed < %.4f)"
          % (min(phase), max(phase), ksPhase, 1.95/math.sqrt(n)))

    # Gaps
    reports = re.findall(r"^Inserted particles: (.*)$", log, re.M)
    gaps = [float(m.group(1)) for m in
            (re.match(r"smallest gap (\S+) m", r) for r in reports) if m]
    far = sum(1 for r in reports if r.startswith("no two closer than"))
    couplingStep = 2e-8     # s: the channel's deltaT
    closing = 4*UMAX/H*(D + GAP)*couplingStep
    check(len(reports) == sum(1 for c in counts if c)
          and len(gaps) + far == len(reports)
          and min(gaps + [GAP]) >= GAP*(1 - 1e-6) - closing,
          "%d insertions checked by the solver (%d with no two closer than a"
          " radius), smallest gap %.6g m (at least %g)"
          % (len(reports), far, min(gaps) if gaps else -1, GAP))
    wall = min(min(x[1], H - x[1]) - r for x, r in zip(p["position"], p["radius"]))
    check(wall >= GAP*(1 - 1e-6), "smallest gap to a wall %.6g m (at least %g)" % (wall, GAP))

    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
