"""Read and plot the contact analysis that colloidDEMFoam writes
(couplingProperties contactAnalysis) in
postProcessing/contactAnalysis/<start time>/: contacts.csv,
contactDurations.csv, agglomerateSizes.csv.  A resumed run adds a folder
per start time; they are joined in time order (rows of an earlier run
after the resumed start are dropped: the resumed run replaces them).

    colloidContactAnalysis [caseDir]   (bin/) summary; contactAnalysis.png

summary(case) gives the figures over the whole run:
    pairFormedPerUs      particle-particle contacts formed per us
    wallFormedPerUs      particle-wall contacts formed per us
    meanPairDuration     mean duration [s] of the pair contacts that ended
                         (0 if none ended)
    pairContacts, wallContacts, agglomerates, largestAgglomerate at the end
    multipleFraction     of the particles touching another, those touching
                         two or more, at the end
Standard library only, but for the plot (matplotlib)."""
import csv
import glob
import os
import sys


def _folders(case):
    root = os.path.join(case, "postProcessing", "contactAnalysis")
    dirs = [d for d in glob.glob(os.path.join(root, "*")) if os.path.isdir(d)]
    if not dirs:
        raise SystemExit("no contact analysis in %s (postProcessing/contactAnalysis; "
                         "contactAnalysis in constant/couplingProperties)" % case)
    return sorted(dirs, key=lambda d: float(os.path.basename(d)))


def _rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def read(case):
    """contacts, durations, sizes: lists of dicts (numbers as float), in
    time order over every start-time folder"""
    out = {"contacts": [], "durations": [], "sizes": []}
    names = {"contacts": "contacts.csv", "durations": "contactDurations.csv",
             "sizes": "agglomerateSizes.csv"}
    timeKey = {"contacts": "time", "durations": "timeEnded", "sizes": "time"}
    folders = _folders(case)
    for k, d in enumerate(folders):
        end = float(os.path.basename(folders[k + 1])) if k + 1 < len(folders) else float("inf")
        for what, name in names.items():
            for row in _rows(os.path.join(d, name)):
                r = {key: (value if key == "kind" else float(value)) for key, value in row.items()}
                if r[timeKey[what]] < end:
                    out[what].append(r)
    return out


def summary(case):
    data = read(case)
    c = data["contacts"]
    if len(c) < 2:
        raise SystemExit("contact analysis in %s: fewer than two analyses" % case)
    span = (c[-1]["time"] - c[0]["time"])/1e-6
    pairs = [d["duration"] for d in data["durations"] if d["kind"] == "pair"]
    last = c[-1]
    touching = last["with1"] + last["with2"] + last["with3orMore"]
    return {
        "pairFormedPerUs": sum(r["pairFormed"] for r in c[1:])/span,
        "wallFormedPerUs": sum(r["wallFormed"] for r in c[1:])/span,
        "meanPairDuration": sum(pairs)/len(pairs) if pairs else 0.0,
        "pairContacts": last["pairContacts"],
        "wallContacts": last["wallContacts"],
        "agglomerates": last["agglomerates"],
        "largestAgglomerate": last["largestAgglomerate"],
        "multipleFraction": (last["with2"] + last["with3orMore"])/touching if touching else 0.0,
    }


def plot(case, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    data = read(case)
    c = data["contacts"]
    t = [r["time"]*1e6 for r in c]
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))

    a = ax[0][0]
    a.plot(t, [r["pairContacts"] for r in c], label="particle-particle contacts")
    a.plot(t, [r["wallContacts"] for r in c], label="particle-wall contacts")
    a.plot(t, [r["agglomeratedParticles"] for r in c], label="particles in agglomerates")
    a.set_xlabel("t [us]")
    a.set_ylabel("count")
    a.legend(fontsize=8)
    a.set_title("Contacts and agglomerated particles")

    a = ax[0][1]
    # formed and broken per us, over windows of about a tenth of the run
    window = max(1, len(c)//10)
    for key, label in (("pairFormed", "pair contacts formed"), ("pairBroken", "pair contacts broken"),
                       ("wallFormed", "wall contacts formed")):
        xs, ys = [], []
        for k in range(1, len(c), window):
            chunk = c[k:k + window]
            dt = (chunk[-1]["time"] - c[k - 1]["time"])/1e-6
            if dt > 0:
                xs.append(0.5*(chunk[-1]["time"] + c[k - 1]["time"])*1e6)
                ys.append(sum(r[key] for r in chunk)/dt)
        a.plot(xs, ys, "o-", label=label, markersize=3)
    a.set_xlabel("t [us]")
    a.set_ylabel("events per us")
    a.legend(fontsize=8)
    a.set_title("Contacts formed and broken")

    a = ax[1][0]
    for kind in ("pair", "wall"):
        d = [r["duration"]*1e9 for r in data["durations"] if r["kind"] == kind]
        if d:
            a.hist(d, bins=30, alpha=0.6, label="%s (%d ended)" % (kind, len(d)))
    a.set_xlabel("contact duration [ns]")
    a.set_ylabel("contacts")
    a.legend(fontsize=8)
    a.set_title("Durations of the contacts that ended")

    a = ax[1][1]
    tEnd = c[-1]["time"]
    sizes = [(r["size"], r["count"]) for r in data["sizes"] if r["time"] == tEnd]
    if sizes:
        a.bar([s for s, _ in sizes], [n for _, n in sizes], width=0.8)
    a.set_xlabel("agglomerate size [particles]")
    a.set_ylabel("agglomerates")
    a.set_title("Agglomerates at t = %.3g us (largest: %d)"
                % (tEnd*1e6, c[-1]["largestAgglomerate"]))
    fig.tight_layout()
    fig.savefig(png, dpi=100)


def main(case):
    """Print the summary and write contactAnalysis.png: 0, or 1 when the
    plot could not be made"""
    for key, value in summary(case).items():
        print("%s %.6g" % (key, value))
    try:
        plot(case, os.path.join(case, "contactAnalysis.png"))
    except ImportError:
        sys.stderr.write("matplotlib missing (Debian: python3-matplotlib): no plot\n")
        return 1
    print("Written %s" % os.path.join(case, "contactAnalysis.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
