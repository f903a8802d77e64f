"""The agglomeration study's report (./Allstudy -report): for each case
folder in study/ with a contact analysis, the figures of the whole run
and the run's cost, as a Markdown table (results/summary.md), and the
particle contacts and agglomerated particles against time of all cases
in one plot (results/contacts.png).

    studyReport.py studyDir resultsDir

Run time and rate: from the case's log.colloidDEMFoam (the last
'ExecutionTime' and 'Timing' lines; a resumed run's log covers its last
part only)."""
import glob
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.environ.get("COLLOIDFOAM_DIR", "../.."), "src", "python"))
import contactAnalysis  # noqa: E402


def cost(case):
    """(end time [s], execution time [s], particle-steps per s per rank)"""
    log = os.path.join(case, "log.colloidDEMFoam")
    end = seconds = rate = float("nan")
    if os.path.exists(log):
        with open(log) as f:
            for line in f:
                m = re.match(r"^Time = (\S+)", line)
                if m:
                    end = float(m.group(1))
                m = re.match(r"^ExecutionTime = (\S+) s", line)
                if m:
                    seconds = float(m.group(1))
                m = re.search(r"; (\S+) particle-steps per second per rank", line)
                if m:
                    rate = float(m.group(1))
    return end, seconds, rate


def main(studyDir, resultsDir):
    cases = sorted(d for d in glob.glob(os.path.join(studyDir, "*"))
                   if os.path.isdir(os.path.join(d, "postProcessing", "contactAnalysis")))
    if not cases:
        raise SystemExit("no case with a contact analysis in %s (./Allstudy <case> first)" % studyDir)
    os.makedirs(resultsDir, exist_ok=True)
    rows = ["| case | end time [µs] | pair contacts formed per µs | pair contacts at the end | "
            "mean duration of ended pair contacts [µs] | wall contacts at the end | agglomerates | largest | "
            "run time [s] | particle-steps/s per rank |",
            "|---|---|---|---|---|---|---|---|---|---|"]
    series = {}
    for case in cases:
        name = os.path.basename(case)
        s = contactAnalysis.summary(case)
        end, seconds, rate = cost(case)
        data = contactAnalysis.read(case)["contacts"]
        # a mean over no ended contact is not a duration of 0
        ended = sum(r["pairBroken"] for r in data[1:])
        duration = "%.3g" % (s["meanPairDuration"]*1e6) if ended else "none ended"
        rows.append("| %s | %.4g | %.3g | %d | %s | %d | %d | %d | %.0f | %.3g |" % (
            name, end*1e6, s["pairFormedPerUs"], s["pairContacts"], duration,
            s["wallContacts"], s["agglomerates"], s["largestAgglomerate"], seconds, rate))
        series[name] = ([r["time"]*1e6 for r in data], [r["pairContacts"] for r in data],
                        [r["agglomeratedParticles"] for r in data])
    with open(os.path.join(resultsDir, "summary.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    for name, (t, pairs, agglomerated) in series.items():
        a.plot(t, pairs, label=name)
        b.plot(t, agglomerated, label=name)
    # counts: from 0, at least to 1 (a case without contacts is a flat line
    # at the bottom, not in the middle of a symmetric range)
    top = max([1] + [max(p + g) for _, p, g in series.values() if p])
    for axis in (a, b):
        axis.set_ylim(0, 1.05*top)
    a.set_xlabel("time [µs]")
    a.set_ylabel("particle-particle contacts")
    b.set_xlabel("time [µs]")
    b.set_ylabel("particles in agglomerates")
    a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(resultsDir, "contacts.png"), dpi=120)
    print("written: %s, %s" % (os.path.join(resultsDir, "summary.md"),
                                os.path.join(resultsDir, "contacts.png")))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
