"""The DPMFoam Goldschmidt column and its colloidDEMFoam twin side by side:
the particles' statistics at every common write time, and what each run
cost.

    /usr/bin/python3 compareGoldschmidt.py DPMCASE COLLOIDCASE OUTDIR

Statistics of the cloud (all particles; ids matched, DPMFoam's origId =
the LIGGGHTS id - 1, both in the order of kinematicCloudPositions):
  mean height      z of the centre of mass [m]
  top              95th percentile of z [m] (the bed's surface once formed)
  mean vz          [m/s]
  rms velocity     sqrt(<|v - <v>|^2>) [m/s], the fluctuations
  moving apart     mean distance between a particle's positions in the
                   two runs [m] (deterministic at first, then as two
                   granular flows from the same start part)

Cost, from the logs: wall time (the last ExecutionTime), steps, particle
steps per core-second (DPMFoam: particles x collision sub-cycles of all
its time steps, as issue 11 counts them; colloidDEMFoam: particles x DEM
steps).  Writes OUTDIR/goldschmidt.csv, OUTDIR/goldschmidt.md and
OUTDIR/goldschmidt.png."""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "src", "python"))
import particleCloud  # noqa: E402


def cloud(case, name, t):
    """positions and velocities by 0-based particle index"""
    d = os.path.join(case, t, "lagrangian", name)
    pos = particleCloud.list_values(os.path.join(d, "positions"), 4)
    vel = particleCloud.list_values(os.path.join(d, "U"), 3)
    ids = particleCloud.list_values(os.path.join(d, "origId"), 1)
    shift = 0 if name == "kinematicCloud" else 1
    out = {}
    for k in range(len(pos)):
        out[int(ids[k][0]) - shift] = (pos[k][:3], vel[k])
    return out


def stats(c):
    n = len(c)
    z = sorted(p[2] for p, v in c.values())
    mean_v = [sum(v[i] for p, v in c.values())/n for i in range(3)]
    fluct = sum(sum((v[i] - mean_v[i])**2 for i in range(3)) for p, v in c.values())/n
    return {"n": n, "meanZ": sum(z)/n, "top": z[int(0.95*(n - 1))], "meanVz": mean_v[2],
            "rmsV": math.sqrt(fluct)}


def times(case, name):
    out = []
    for t in os.listdir(case):
        try:
            float(t)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, t, "lagrangian", name)):
            out.append(t)
    return {float(t): t for t in out}


def cost(log, particles, until, interval):
    """Wall time, steps and particle-steps per second of a run up to the
    simulated time until [s]: the ExecutionTime of that time step, the
    collision sub-cycles (DPMFoam, interval None) or DEM steps (interval
    per time step) of the steps before it"""
    t, wall, steps = None, None, 0
    for line in open(log):
        m = re.match(r"^Time = ([0-9.eE+-]+)\s*$", line)
        if m:
            t = float(m.group(1))
            if t > until*(1 + 1e-9):
                break
            steps += interval or 1
            continue
        # DPMFoam prints its sub-cycles only when there are more than one
        m = re.match(r"^\s*(\d+) move-collide subCycles", line)
        if m and interval is None and t is not None:
            steps += int(m.group(1)) - 1
        m = re.match(r"^ExecutionTime = ([0-9.eE+-]+) s", line)
        if m and t is not None:
            wall = float(m.group(1))
    if wall is None or t is None or t < until*(1 - 1e-9):
        sys.exit("compareGoldschmidt: %s does not reach t = %g s" % (log, until))
    return {"wall": wall, "steps": steps, "rate": particles*steps/wall}


def main():
    dpm_case, cf_case, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    dpm_times = times(dpm_case, "kinematicCloud")
    cf_times = times(cf_case, "particles")
    common = sorted(t for t in dpm_times if any(abs(t - s) < 1e-9 for s in cf_times))
    if not common:
        sys.exit("compareGoldschmidt: no common write time in %s and %s" % (dpm_case, cf_case))
    rows = []
    for t in common:
        a = cloud(dpm_case, "kinematicCloud", dpm_times[t])
        b = cloud(cf_case, "particles", cf_times[min(cf_times, key=lambda s: abs(s - t))])
        sa, sb = stats(a), stats(b)
        shared = set(a) & set(b)
        apart = sum(math.dist(a[i][0], b[i][0]) for i in shared)/max(len(shared), 1)
        rows.append((t, sa, sb, apart))
    n = rows[-1][1]["n"]
    end = common[-1]
    cd = cost(os.path.join(dpm_case, "log.DPMFoam"), n, end, None)
    interval = re.search(r"couplingInterval\s+(\d+)", open(os.path.join(cf_case, "constant", "couplingProperties")).read())
    cc = cost(os.path.join(cf_case, "log.colloidDEMFoam"), n, end, int(interval.group(1)))

    with open(os.path.join(out, "goldschmidt.csv"), "w") as f:
        f.write("time_s,particles_dpm,particles_cf,meanZ_dpm_m,meanZ_cf_m,top_dpm_m,top_cf_m,"
                "meanVz_dpm_mps,meanVz_cf_mps,rmsV_dpm_mps,rmsV_cf_mps,apart_m\n")
        for t, sa, sb, apart in rows:
            f.write("%g,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n"
                    % (t, sa["n"], sb["n"], sa["meanZ"], sb["meanZ"], sa["top"], sb["top"],
                       sa["meanVz"], sb["meanVz"], sa["rmsV"], sb["rmsV"], apart))
    lines = ["| t [s] | mean height [mm] DPMFoam / colloidFoam | top (95 %) [mm] | mean vz [m/s] | rms velocity [m/s] | moving apart [mm] |",
             "|---|---|---|---|---|---|"]
    for t, sa, sb, apart in rows:
        lines.append("| %g | %.2f / %.2f | %.2f / %.2f | %.4f / %.4f | %.4f / %.4f | %.3f |"
                     % (t, 1e3*sa["meanZ"], 1e3*sb["meanZ"], 1e3*sa["top"], 1e3*sb["top"],
                        sa["meanVz"], sb["meanVz"], sa["rmsV"], sb["rmsV"], 1e3*apart))
    lines += ["", "| run | wall time [s] | particle-steps | particle-steps per core-second |", "|---|---|---|---|",
              "| DPMFoam (collision sub-cycles) | %.1f | %.4g | %.3g |" % (cd["wall"], cd["steps"]*n, cd["rate"]),
              "| colloidDEMFoam (DEM steps) | %.1f | %.4g | %.3g |" % (cc["wall"], cc["steps"]*n, cc["rate"]),
              "", "colloidDEMFoam / DPMFoam to the same simulated time (%g s): %.1f times faster; "
              "per particle-step %.1f times" % (end, cd["wall"]/cc["wall"], cc["rate"]/cd["rate"])]
    text = "\n".join(lines) + "\n"
    open(os.path.join(out, "goldschmidt.md"), "w").write(text)
    print(text)

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("compareGoldschmidt: no matplotlib (use Debian's /usr/bin/python3): no plot")
        return
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    t = [r[0] for r in rows]
    for k, (key, label, scale) in enumerate([("meanZ", "mean height [mm]", 1e3), ("meanVz", "mean vz [m/s]", 1),
                                              ("rmsV", "rms velocity [m/s]", 1)]):
        ax[k].plot(t, [scale*r[1][key] for r in rows], "o-", label="DPMFoam")
        ax[k].plot(t, [scale*r[2][key] for r in rows], "s--", label="colloidDEMFoam")
        ax[k].set_xlabel("t [s]")
        ax[k].set_ylabel(label)
        ax[k].grid(alpha=0.3)
    ax[0].legend()
    fig.suptitle("Goldschmidt column, %d particles: DPMFoam %.0f s, colloidDEMFoam %.0f s" % (n, cd["wall"], cc["wall"]))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "goldschmidt.png"), dpi=110)


main()
