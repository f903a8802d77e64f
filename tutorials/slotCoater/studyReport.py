"""The agglomeration study's report (./Allstudy -report): for each case
folder in study/ with a contact analysis, the figures of the whole run
and the run's cost, as a Markdown table (results/summary.md), and the
particle contacts, agglomerated particles, agglomerates and the largest
agglomerate's size against time of all cases in one figure
(results/contacts.png).  Where the agglomerates are at each
case's last write (results/where.md: each agglomerate's particles by id,
its centre, height above the substrate and part of the die; where.png:
the centres on the die's outline): from the written particle cloud, the
particles with agglomerateSize > 1 grouped by their agglomerateId, as the
run's analysis grouped them (in clouds written before the id, by the
gaps: below contactAnalysis/agglomerateGap of the smaller radius, or
below releaseGap, where a contact lasts: constant/couplingProperties;
across the periodic span).

    studyReport.py studyDir resultsDir

Pairs held near contact (results/gaps.md, gaps.png): at every write of
each case, the pairs of particles closer than 50 nm that do not touch
(surface gap at least the agglomerate gap of the smaller radius, and not
a contact that the release gap holds), the
closest of them, and how many lie within 5, 10, 20 and 50 nm: the pairs
the shear has brought together and the double layer holds apart, which
the contact counts do not show.

At the seeds' 60 and 110 us and on to the liquid's residence time
(results/milestones.md, MILESTONES_US): each case's contacts, agglomerates
and particles in them at each of these times its analysis reached, and at
its last analysis, with the contacts formed and ended in between: the
growth a single end-of-run row hides.  where.md begins with the
agglomerates of each case counted by part of the die and size.

A case beside its numerical or model variant (the same case name with a
suffix of VARIANT_SUFFIXES, both in the study: results/variants.md): the contacts
and agglomerates of the two, and how many agglomerates are the same
particles (write_variants).

The counts of each write are kept in the case
(postProcessing/closePairs/closePairs.csv) and not computed again.

Run time and rate: from the case's log.colloidDEMFoam, and the logs of
the earlier parts of a resumed run (log.colloidDEMFoam.to<time>): the
wall-clock 'ClockTime' of the parts summed, the particle-steps per second
per rank over them (their last 'Timing' lines)."""
import functools
import glob
import itertools
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.environ.get("COLLOIDFOAM_DIR", "../.."), "src", "python"))
import contactAnalysis  # noqa: E402
import foamDict  # noqa: E402
import numpy as np  # noqa: E402
import pairGaps  # noqa: E402
import particleCloud  # noqa: E402


def run_logs(case):
    """The logs of a case's coupled run, in order: the earlier parts of a
    resumed run (log.colloidDEMFoam.to<time>, numbered .to<time>.<n> when
    resumed from one write more than once: Allrun -resume), then
    log.colloidDEMFoam; other files named alike (backups) are not logs"""
    kept = []
    for f in glob.glob(os.path.join(case, "log.colloidDEMFoam.to*")):
        m = re.search(r"\.to([-+]?\d*\.?\d+(?:[eE][-+]?\d+)?)(?:\.(\d+))?$", f)
        if m:
            kept.append(((float(m.group(1)), int(m.group(2) or 1)), f))
    logs = [f for _, f in sorted(kept)] + [os.path.join(case, "log.colloidDEMFoam")]
    return [f for f in logs if os.path.exists(f)]


def cost(case):
    """(end time [s], wall-clock run time [s], particle-steps per s per
    rank) of the whole run: the parts of a resumed run summed (their
    'ClockTime'; a part that was killed counts the steps after its last
    write, which the resume does again), the rate over their last
    'Timing' lines (DEM and coupling wall-clock time)"""
    end = float("nan")
    seconds = steps = timed = 0.0
    for log in run_logs(case):
        part_seconds = part_rate = part_timed = 0.0
        with open(log) as f:
            for line in f:
                m = re.match(r"^Time = (\S+)", line)
                if m:
                    end = float(m.group(1))
                m = re.match(r"^ExecutionTime = \S+ s +ClockTime = (\S+) s", line)
                if m:
                    part_seconds = float(m.group(1))
                m = re.match(r"^Timing \(master, wall clock\): DEM (\S+) s, coupling (\S+) s; "
                             r"(\S+) particle-steps per second per rank", line)
                if m:
                    part_timed = float(m.group(1)) + float(m.group(2))
                    part_rate = float(m.group(3))
        seconds += part_seconds
        steps += part_rate*part_timed       # particle-steps per rank
        timed += part_timed
    return end, seconds or float("nan"), steps/timed if timed else float("nan")


def geometry(case):
    """The die's dimensions [m] (system/slotCoaterParameters)"""
    d = foamDict.read(os.path.join(case, "system", "slotCoaterParameters"))
    return {k: float(d[k]) for k in ("gap", "slotWidth", "slotLength", "upstreamLip",
                                     "downstreamLip", "span")}


def agglomerate_gap(case):
    """The analysis' bond gap over the smaller radius: touching pairs and
    those below contactAnalysis/agglomerateGap (couplingProperties; the
    coupling's defaults: agglomerateGap = touchingGap = 0.01)"""
    d = foamDict.read(os.path.join(case, "constant", "couplingProperties")).get("contactAnalysis", {})
    touching = float(d.get("touchingGap", 0.01))
    return max(float(d.get("agglomerateGap", touching)), touching)


def release_gap(case):
    """The gap over the smaller radius up to which a contact, once formed,
    lasts and bonds its agglomerate (contactAnalysis/releaseGap; default
    touchingGap), or the bond gap if that is larger"""
    d = foamDict.read(os.path.join(case, "constant", "couplingProperties")).get("contactAnalysis", {})
    return max(float(d.get("releaseGap", d.get("touchingGap", 0.01))), agglomerate_gap(case))


# the parts of the die (part_of_die), upstream to downstream
DIE_PARTS = ("under the upstream lip", "below the slot", "under the downstream lip", "in the slot")


def part_of_die(g, x, y):
    """The part of the die above a point (one of DIE_PARTS): x along the
    web from the slot's upstream wall, y up from the substrate"""
    upstreamLip, belowSlot, downstreamLip, inSlot = DIE_PARTS
    if y > g["gap"]:
        return inSlot
    if x < 0:
        return upstreamLip
    if x <= g["slotWidth"]:
        return belowSlot
    return downstreamLip


def periodic_offset(cloud, span, a, b):
    """Position of particle a relative to b [m], across the periodic span"""
    d = [cloud["position"][a][j] - cloud["position"][b][j] for j in range(3)]
    d[2] -= span*round(d[2]/span)
    return d


def group_agglomerated(case, cloud):
    """The particles of a cloud with agglomerateSize > 1 joined as the
    run's analysis joined them: (members, their group's root by member,
    bonds by member).  From the cloud's agglomerateId where the run wrote
    it (bonds: the pairs of an agglomerate within the release gap, which
    hold every contact and bond of it); in older runs' clouds, bonded:
    below the bond gap; or within the release gap, where a contact once
    formed lasts, if the particles' agglomerate sizes allow it (two
    agglomerates that near each other without a contact stay apart; the
    closest pair first, so the grouping can differ from the run's)"""
    span = geometry(case)["span"]
    size = cloud["agglomerateSize"]
    members = [k for k, n in enumerate(size) if n > 1]
    ids = cloud.get("agglomerateId")
    by_id = ids is not None and all(ids[k] is not None for k in members)
    root = {k: k for k in members}
    count = {k: 1 for k in members}
    bonds = {k: [] for k in members}

    def find(k):
        while root[k] != k:
            root[k] = root[root[k]]
            k = root[k]
        return k

    def join(a, b):
        ra, rb = find(a), find(b)
        if ra != rb:
            root[ra] = rb
            count[rb] += count[ra]
        bonds[a].append(b)
        bonds[b].append(a)

    bond, release = agglomerate_gap(case), release_gap(case)
    # the pairs to look at: of one agglomerate (by id), or all
    sets = {}
    for k in members:
        sets.setdefault(ids[k] if by_id else 0, []).append(k)
    held = []
    for ks in sets.values():
        for i, a in enumerate(ks):
            for b in ks[i + 1:]:
                d = periodic_offset(cloud, span, a, b)
                ra, rb = cloud["radius"][a], cloud["radius"][b]
                gap = sum(x*x for x in d)**0.5 - ra - rb
                if gap < (release if by_id else bond)*min(ra, rb):
                    join(a, b)
                elif gap < release*min(ra, rb):
                    held.append((gap, a, b))
    if by_id:
        return members, {k: sets[ids[k]][0] for k in members}, bonds
    # the closest first, the likelier contact (the cloud holds each
    # particle's agglomerate size, not its agglomerate)
    for _, a, b in sorted(held):
        if find(a) != find(b) and count[find(a)] + count[find(b)] <= min(size[a], size[b]):
            join(a, b)
    return members, {k: find(k) for k in members}, bonds


def agglomerates(case, write=None):
    """(write time [s], [(ids, centre [m], die part)]) at the case's last
    write (or the write time folder write): the particles with
    agglomerateSize > 1 grouped as the run's analysis grouped them
    (group_agglomerated).  Found once per write in a report (where.md and
    variants.md both ask for a case's last write); not to be changed by
    the caller"""
    return _agglomerates_at(case, write or particleCloud.latest(case))


@functools.lru_cache(maxsize=None)
def _agglomerates_at(case, last):
    g = geometry(case)
    cloud = particleCloud.read(last)
    members, root, bonds = group_agglomerated(case, cloud)

    def offset(a, b):
        return periodic_offset(cloud, g["span"], a, b)

    groups = {}
    for k in members:
        groups.setdefault(root[k], []).append(k)
    found = []
    for ks in groups.values():
        # each member's place relative to the first, summed along the bonds
        # (an agglomerate may be wider than half the span)
        first = ks[0]
        rel = {first: [0.0, 0.0, 0.0]}
        todo = [first]
        while todo:
            a = todo.pop()
            for b in bonds[a]:
                if b not in rel:
                    d = offset(b, a)
                    rel[b] = [rel[a][j] + d[j] for j in range(3)]
                    todo.append(b)
        # a member no bond reaches (its link is a particle outside the
        # fluid mesh, which the cloud does not hold): the nearest image
        for b in ks:
            if b not in rel:
                rel[b] = offset(b, first)
        c = [cloud["position"][first][j] + sum(r[j] for r in rel.values())/len(ks)
             for j in range(3)]
        c[2] %= g["span"]       # back into the span (the DEM's z from 0)
        found.append((sorted(cloud["id"][k] for k in ks), c, part_of_die(g, c[0], c[1])))
    return particleCloud.time(last), sorted(found, key=lambda f: f[1][0])


# bounds [m] of the close-pair counts (the last one bounds the search)
NEAR_GAPS = (5e-9, 10e-9, 20e-9, 50e-9)


def close_pairs(case, path):
    """Counts of the pairs at one write that do not touch and lie within
    each of NEAR_GAPS, and the closest such gap [m] (nan if none)"""
    cloud = particleCloud.read(path)
    i, j, gap = pairGaps.close_pairs(cloud["position"], cloud["radius"],
                                     geometry(case)["span"], NEAR_GAPS[-1])
    r = np.array(cloud["radius"])
    r_min = np.minimum(r[i], r[j])
    # not touching: beyond the bond gap, and not a contact that the release
    # gap holds (within it, in one agglomerate)
    apart = gap >= agglomerate_gap(case)*r_min
    maybe_held = np.nonzero(apart & (gap < release_gap(case)*r_min))[0]
    if len(maybe_held):
        root = group_agglomerated(case, cloud)[1]
        for k in maybe_held:
            a, b = int(i[k]), int(j[k])
            apart[k] = a not in root or root[a] != root.get(b)
    held = gap[apart]
    return [int((held < g).sum()) for g in NEAR_GAPS], float(held[0] if len(held) else "nan")


def close_pair_series(case):
    """(write times [s], counts, closest gaps [m]) of every write of a
    case: from the case's postProcessing/closePairs/closePairs.csv where
    it holds the write with the same touching gap, else computed (about
    10 s per write of 2e5 particles) and added to it"""
    folder = os.path.join(case, "postProcessing", "closePairs")
    path = os.path.join(folder, "closePairs.csv")
    touching = "# touching below %r of the smaller radius" % agglomerate_gap(case)
    if release_gap(case) > agglomerate_gap(case):
        touching += "; contacts held to %r" % release_gap(case)
    header = "time,closestGap," + ",".join("within%gnm" % (g*1e9) for g in NEAR_GAPS)
    known = {}
    if os.path.exists(path):
        with open(path) as f:
            lines = f.read().splitlines()
        if lines[:2] == [touching, header]:
            for line in lines[2:]:
                v = line.split(",")
                known[v[0]] = ([int(k) for k in v[2:]], float(v[1]))
    times, counts, closest = [], [], []
    for write in particleCloud.write_times(case):
        name = os.path.basename(write)
        if name not in known:
            known[name] = close_pairs(case, write)
        times.append(particleCloud.time(write))
        counts.append(known[name][0])
        closest.append(known[name][1])
    os.makedirs(folder, exist_ok=True)
    with open(path + ".tmp", "w") as f:
        f.write("%s\n%s\n" % (touching, header))
        for name in sorted(known, key=float):
            f.write("%s,%r,%s\n" % (name, known[name][1], ",".join(str(k) for k in known[name][0])))
    os.replace(path + ".tmp", path)
    return times, counts, closest


def write_gaps(cases, resultsDir):
    """results/gaps.md (each case's last write) and gaps.png (against time)"""
    bounds = " | ".join("within %g nm" % (g*1e9) for g in NEAR_GAPS)
    rows = ["| case | write time [µs] | closest gap below %g nm of the pairs not touching [nm] "
            "| %s |" % (NEAR_GAPS[-1]*1e9, bounds),
            "|---|---|---|" + "---|"*len(NEAR_GAPS)]
    series = {}
    for case in cases:
        name = os.path.basename(case)
        times, counts, closest = close_pair_series(case)
        times = [t*1e6 for t in times]
        series[name] = (times, counts)
        rows.append("| %s | %.4g | %s | %s |" % (
            name, times[-1], "none" if closest[-1] != closest[-1] else "%.3g" % (closest[-1]*1e9),
            " | ".join(str(k) for k in counts[-1])))
    with open(os.path.join(resultsDir, "gaps.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for axis, k in zip(axes, (1, len(NEAR_GAPS) - 1)):
        for name, (t, counts) in series.items():
            axis.plot(t, [c[k] for c in counts], "o-", ms=3, label=name)
        axis.set_xlabel("time [µs]")
        axis.set_ylabel("pairs within %g nm, not touching" % (NEAR_GAPS[k]*1e9))
        axis.set_ylim(bottom=0)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(resultsDir, "gaps.png"), dpi=120)
    print("written: %s, %s" % (os.path.join(resultsDir, "gaps.md"),
                                os.path.join(resultsDir, "gaps.png")))


# the agglomerate sizes [particles] counted apart in where.md's first
# table, by part of the die (DIE_PARTS)
SIZE_CLASSES = ((2, 2), (3, 3), (4, 4), (5, 9), (10, None))


def where_counts(groups):
    """Rows (part of the die, agglomerates, their count in each of
    SIZE_CLASSES, particles) for each part holding one, and 'all'"""
    def row(label, sizes):
        classes = [sum(1 for n in sizes if n >= lo and (hi is None or n <= hi))
                   for lo, hi in SIZE_CLASSES]
        return (label, len(sizes), classes, sum(sizes))
    out = []
    for part in DIE_PARTS:
        sizes = [len(ids) for ids, _, p in groups if p == part]
        if sizes:
            out.append(row(part, sizes))
    out.append(row("all", [len(ids) for ids, _, _ in groups]))
    return out


def write_where(cases, resultsDir):
    """results/where.md (how many agglomerates of each size in each part
    of the die, then each agglomerate) and where.png"""
    labels = ["%d" % lo if hi == lo else ("%d-%d" % (lo, hi) if hi else "%d or more" % lo)
              for lo, hi in SIZE_CLASSES]
    counts = ["| case | write time [µs] | part of the die | agglomerates | %s | particles |" % (
                  " | ".join("of %s" % k for k in labels)),
              "|---|---|---|---|%s---|" % ("---|"*len(labels))]
    rows = ["| case | write time [µs] | particles (ids) | centre x, z [µm] | "
            "centre's height above the substrate [µm] | part of the die |",
            "|---|---|---|---|---|---|"]
    found = {}
    for case in cases:
        name = os.path.basename(case)
        t, groups = agglomerates(case)
        found[name] = groups
        for part, n, classes, particles in where_counts(groups):
            counts.append("| %s | %.4g | %s | %d | %s | %d |" % (
                name, t*1e6, part, n, " | ".join(str(c) for c in classes), particles))
        if not groups:
            rows.append("| %s | %.4g | none | | | |" % (name, t*1e6))
        for ids, c, part in groups:
            rows.append("| %s | %.4g | %s | %.2f, %.2f | %.2f | %s |" % (
                name, t*1e6, " ".join(str(i) for i in ids), c[0]*1e6, c[2]*1e6,
                c[1]*1e6, part))
    with open(os.path.join(resultsDir, "where.md"), "w") as f:
        f.write("\n".join(counts) + "\n\n" + "\n".join(rows) + "\n")
    print("\n".join(counts + [""] + rows))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    g = {k: v*1e6 for k, v in geometry(cases[0]).items()}
    fig, (a, zoom) = plt.subplots(2, 1, figsize=(11, 7))
    # the die's walls and the substrate (x, y in um); below, the layer
    # next to the substrate enlarged
    xu, xd = -g["upstreamLip"], g["slotWidth"] + g["downstreamLip"]
    top = g["gap"] + g["slotLength"]
    for axis in (a, zoom):
        axis.plot([xu, xd], [0, 0], "k-", lw=2, label="substrate (moving)")
        axis.plot([xu, xu, 0, 0], [0, g["gap"], g["gap"], top], "k-", lw=1)
        axis.plot([g["slotWidth"], g["slotWidth"], xd], [top, g["gap"], g["gap"]], "k-",
                  lw=1, label="die")
        for marker, (name, groups) in zip(itertools.cycle("osd^v<>p"), found.items()):
            axis.plot([c[0]*1e6 for _, c, _ in groups], [c[1]*1e6 for _, c, _ in groups],
                      marker, ls="none", mfc="none", label="%s (%d)" % (name, len(groups)))
        axis.set_xlabel("x along the web [µm]")
        axis.set_ylabel("y above the substrate [µm]")
    a.set_title("Agglomerates at each case's last write")
    a.legend(fontsize=8, loc="center")
    zoom.set_ylim(-0.2, 0.1*g["gap"])
    zoom.set_title("the layer next to the substrate")
    fig.tight_layout()
    fig.savefig(os.path.join(resultsDir, "where.png"), dpi=120)
    print("written: %s, %s" % (os.path.join(resultsDir, "where.md"),
                                os.path.join(resultsDir, "where.png")))


# the times of results/milestones.md [µs]: the seeds' 60 and 110 µs, and
# on to the liquid's residence time in the die, about 500 µs (README)
MILESTONES_US = (60, 110, 200, 300, 400, 500)
# the analysis' times are multiples of the coupling step (1e-8 s or more),
# kept to round-off: a time within this of a milestone is at it [s]
TIME_MATCH = 1e-12


def write_milestones(cases, resultsDir):
    """results/milestones.md: each case's contacts and agglomerates at the
    milestones its analysis reached (the last analysis at or before each),
    and at its last analysis if later, with the pair contacts formed and
    ended since the row before (from the first analysis for the first
    row); an analysis is given once (milestones between two analyses
    share the earlier one's row)"""
    rows = ["| case | time [µs] | pair contacts | wall contacts | agglomerates | "
            "particles in agglomerates (share of those present) | largest | "
            "pair contacts formed / ended since the row before | formed per µs since the row before |",
            "|---|---|---|---|---|---|---|---|---|"]
    for case in cases:
        name = os.path.basename(case)
        data = contactAnalysis.read(case)["contacts"]
        last = data[-1]["time"]
        times = [t*1e-6 for t in MILESTONES_US if t*1e-6 <= last + TIME_MATCH]
        if not times or last > times[-1] + TIME_MATCH:
            times.append(last)
        before, k = data[0]["time"], 0
        formed = ended = 0
        for t in times:
            shown = k
            while k + 1 < len(data) and data[k + 1]["time"] <= t + TIME_MATCH:
                k += 1
                formed += data[k]["pairFormed"]
                ended += data[k]["pairBroken"]
            if k == shown:
                continue        # no analysis since the row before
            r = data[k]
            interval = (r["time"] - before)/1e-6
            rows.append("| %s | %.4g | %d | %d | %d | %d (%.3g %%) | %d | %d / %d | %s |" % (
                name, r["time"]*1e6, r["pairContacts"], r["wallContacts"], r["agglomerates"],
                r["agglomeratedParticles"], 100*r["agglomeratedParticles"]/r["particles"],
                r["largestAgglomerate"], formed, ended,
                "%.3g" % (formed/interval) if interval > 0 else ""))
            before, formed, ended = r["time"], 0, 0
    with open(os.path.join(resultsDir, "milestones.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))
    print("written: %s" % os.path.join(resultsDir, "milestones.md"))


# suffixes of the study's numerical and model variants (Allstudy): the
# same case at other numerical settings (softer contacts at twice the DEM
# step; the weak lubricated pairs damped explicitly; the colloid cut-offs
# at 0.025 or 0.1 um) or with the two-sphere hydrodynamics, compared with
# it in results/variants.md
VARIANT_SUFFIXES = ("SoftContacts", "TwoSphere", "Explicit", "ShortRange", "LongRange")


def write_variants(cases, resultsDir):
    """results/variants.md: each case run at a numerical variant beside
    the same case without it (both in the study), at the latest write time
    the two have in common: their pair contacts (there, or at the last
    analysis time before it the two share, said so) and agglomerates; of
    the case's agglomerates, how many are the same particles in the
    variant (identical members) and how many have two or more members in
    one of the variant's (the identical ones among them); the largest
    difference of the pair contact counts over the analysis times they
    have in common up to the write; the run times of the whole runs (with
    their end times where these differ).  A pair without a write and an
    analysis time in common is named and left out; nothing is written
    when no case has its variant."""
    by_name = {os.path.basename(c): c for c in cases}
    rows = ["| case | variant | write time compared [µs] | pair contacts (case / variant) | "
            "largest difference of pair contacts at a common time | agglomerates (case / variant) | "
            "the case's found as the same particles | the case's with two or more members in one of "
            "the variant's | run time [s] (case / variant) |",
            "|---|---|---|---|---|---|---|---|---|"]

    def ns(t):
        return int(round(t*1e9))

    for name, case in sorted(by_name.items()):
        for suffix in VARIANT_SUFFIXES:
            variant = by_name.get(name + suffix)
            if variant is None:
                continue
            writes = [{ns(particleCloud.time(w)): w for w in particleCloud.write_times(c)}
                      for c in (case, variant)]
            both = sorted(set(writes[0]) & set(writes[1]))
            counts = [{ns(r["time"]): r["pairContacts"] for r in contactAnalysis.read(c)["contacts"]}
                      for c in (case, variant)]
            common = [t for t in sorted(set(counts[0]) & set(counts[1])) if both and t <= both[-1]]
            if not common:
                print("%s and %s: no write time with analysis times in common, not compared"
                      % (name, name + suffix))
                continue
            write, at = both[-1], common[-1]
            # the contacts at the write compared, or at the last analysis
            # time before it that the two have in common (said so)
            when = "%.4g" % (write*1e-3) if at == write else \
                "%.4g (contacts at %.4g)" % (write*1e-3, at*1e-3)
            largest = max(abs(counts[0][t] - counts[1][t]) for t in common)
            (_, gc), (_, gv) = agglomerates(case, writes[0][write]), agglomerates(variant, writes[1][write])
            sets_c = [frozenset(ids) for ids, _, _ in gc]
            sets_v = [frozenset(ids) for ids, _, _ in gv]
            same = len(set(sets_c) & set(sets_v))
            sharing = sum(1 for a in sets_c if any(len(a & b) >= 2 for b in sets_v))
            # whole runs' times: their end times too when they differ
            (end_c, seconds_c, _), (end_v, seconds_v, _) = cost(case), cost(variant)
            seconds = "%.0f / %.0f" % (seconds_c, seconds_v)
            if abs(end_c - end_v) > 1e-12:
                seconds += " (runs to %.4g / %.4g µs)" % (end_c*1e6, end_v*1e6)
            rows.append("| %s | %s | %s | %d / %d | %d | %d / %d | %d | %d | %s |" % (
                name, suffix, when, counts[0][at], counts[1][at], largest,
                len(gc), len(gv), same, sharing, seconds))
    if len(rows) == 2:
        return
    path = os.path.join(resultsDir, "variants.md")
    with open(path, "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))
    print("written: %s" % path)


def main(studyDir, resultsDir):
    cases = sorted(d for d in glob.glob(os.path.join(studyDir, "*"))
                   if os.path.isdir(os.path.join(d, "postProcessing", "contactAnalysis")))
    if not cases:
        raise SystemExit("no case with a contact analysis in %s (./Allstudy <case> first)" % studyDir)
    os.makedirs(resultsDir, exist_ok=True)
    rows = ["| case | end time [µs] | pair contacts formed per µs | pair contacts at the end | "
            "mean duration of ended pair contacts [µs] | wall contacts at the end | agglomerates | largest | "
            "wall-clock run time [s] | particle-steps/s per rank |",
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
                        [r["agglomeratedParticles"] for r in data],
                        [r["agglomerates"] for r in data], [r["largestAgglomerate"] for r in data])
    with open(os.path.join(resultsDir, "summary.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator
    # contacts and the agglomerates they make: how many particles, how many
    # agglomerates, how large the largest
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    panels = ((1, "particle-particle contacts"), (2, "particles in agglomerates"),
              (3, "agglomerates"), (4, "particles in the largest agglomerate"))
    for axis, (k, label) in zip(axes.flat, panels):
        for name, columns in series.items():
            axis.plot(columns[0], columns[k], label=name)
        # counts: from 0, at least to 1 (a case without contacts is a flat
        # line at the bottom, not in the middle of a symmetric range)
        axis.set_ylim(0, 1.05*max([1] + [max(c[k]) for c in series.values() if c[k]]))
        axis.yaxis.set_major_locator(MaxNLocator(integer=True))
        axis.set_xlabel("time [µs]")
        axis.set_ylabel(label)
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(resultsDir, "contacts.png"), dpi=120)
    print("written: %s, %s" % (os.path.join(resultsDir, "summary.md"),
                                os.path.join(resultsDir, "contacts.png")))
    write_milestones(cases, resultsDir)
    write_where(cases, resultsDir)
    write_gaps(cases, resultsDir)
    write_variants(cases, resultsDir)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
