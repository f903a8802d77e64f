#!/usr/bin/env python3
"""Checks the first analysis of runArrangementTest.sh (the start) against
the arrangement's contacts and clusters, known by construction
(writeArrangement.py), each particle's agglomerateSize and agglomerateId
in the time-0 cloud, and the time-0 cell fields (contactCellFields.H): in every cell of
every rank, density x cell volume = the particles, pair contacts (half
per particle), wall contacts and agglomerated particles that the
arrangement puts in the cell (by the cloud's cell of each particle;
relative tolerance 1e-9), and the same totals summed over all cells.

usage: checkArrangement.py caseDir serial|parallel"""
import csv
import glob
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "src", "python"))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "fluidCommon"))
import foamFields  # noqa: E402
import particleCloud  # noqa: E402
from writeArrangement import GROUPS  # noqa: E402

SIZE = {"chain5": 5, "ring6": 6, "pair": 2, "pairAcrossRanks": 2,
        "chain3AcrossPeriodic": 3, "loosePair": 2, "isolated": 1, "onWall": 1}
# Pair contacts of each particle of a group, in its order
CONTACTS = {"chain5": [1, 2, 2, 2, 1], "ring6": [2]*6, "pair": [1, 1],
            "pairAcrossRanks": [1, 1], "chain3AcrossPeriodic": [1, 2, 1],
            "loosePair": [0, 0], "isolated": [0], "onWall": [0]}
WALL = {"onWall"}
CELL_VOLUME = 10e-6*5e-6*10e-6      # the channel's cells [m^3]
FIELDS = ("particleNumberDensity", "pairContactDensity", "wallContactDensity",
          "agglomeratedNumberDensity")


def expectedPerParticle():
    """Per particle id: (1, pair contacts/2, wall contacts, agglomerated)"""
    values = {}
    pid = 0
    for name, centres in GROUPS:
        for k in range(len(centres)):
            pid += 1
            values[pid] = (1.0, 0.5*CONTACTS[name][k], 1.0 if name in WALL else 0.0,
                           1.0 if SIZE[name] > 1 else 0.0)
    return values


def checkCellFields(case, check):
    """Each rank's time-0 fields against its cloud's particles"""
    per = expectedPerParticle()
    clouds = particleCloud._cloud_dirs(os.path.join(case, "0"))
    totals = [0.0]*len(FIELDS)
    worst = 0.0
    for cloudDir in clouds:
        timeDir = os.path.dirname(os.path.dirname(cloudDir))
        positions = particleCloud.list_values(os.path.join(cloudDir, "positions"), 4)
        ids = particleCloud.list_values(os.path.join(cloudDir, "origId"), 1)
        want = {}
        for pos, (pid,) in zip(positions, ids):
            cell = want.setdefault(int(pos[3]), [0.0]*len(FIELDS))
            for j, v in enumerate(per[int(pid)]):
                cell[j] += v
        for j, name in enumerate(FIELDS):
            got = foamFields.read_internal_field(os.path.join(timeDir, name))
            for celli, density in enumerate(got):
                count = density*CELL_VOLUME
                expected = want.get(celli, [0.0]*len(FIELDS))[j]
                worst = max(worst, abs(count - expected)/max(1.0, expected))
                totals[j] += count
    check("worst cell of the cell fields (relative)", worst <= 1e-9, True)
    check("cell fields summed: particles, pair and wall contacts, agglomerated",
          tuple(round(t, 6) for t in totals), (22.0, 14.0, 1.0, 20.0))


def main():
    case = sys.argv[1]
    ok = True

    def check(what, got, want):
        nonlocal ok
        good = got == want
        print("%-40s %-20s expected %-20s %s" % (what, got, want, "ok" if good else "FAIL"))
        ok = ok and good

    files = glob.glob(os.path.join(case, "postProcessing", "contactAnalysis", "*", "contacts.csv"))
    if len(files) != 1:
        print("FAIL: expected one contacts.csv, found %s" % files)
        return 1
    rows = list(csv.DictReader(l for l in open(files[0]) if not l.startswith("#")))
    first = rows[0]
    check("time of the first analysis", float(first["time"]), 0.0)
    check("particles", int(first["particles"]), 22)
    check("particle contacts", int(first["pairContacts"]), 14)
    check("wall contacts", int(first["wallContacts"]), 1)
    check("formed at the start", int(first["pairFormed"]), 0)
    check("particles with 0/1/2/3+ contacts",
          tuple(int(first[k]) for k in ("with0", "with1", "with2", "with3orMore")), (4, 8, 10, 0))
    check("agglomerates", int(first["agglomerates"]), 6)
    check("particles in agglomerates", int(first["agglomeratedParticles"]), 20)
    check("largest agglomerate", int(first["largestAgglomerate"]), 6)
    sizes = {}
    for row in csv.DictReader(open(os.path.join(os.path.dirname(files[0]), "agglomerateSizes.csv"))):
        if float(row["time"]) == 0.0:
            sizes[int(row["size"])] = int(row["count"])
    check("agglomerate sizes at the start", sizes, {2: 3, 3: 1, 5: 1, 6: 1})

    # the cloud at time 0: each particle's agglomerate size and id, the
    # smallest id in its agglomerate, its own in none (ids follow the
    # creation order of the groups, from 1)
    cloud = particleCloud.read(os.path.join(case, "0"))
    want, wantId = [], []
    for name, centres in GROUPS:
        first = len(want) + 1
        want += [SIZE[name]]*len(centres)
        wantId += [first if SIZE[name] > 1 else first + k for k in range(len(centres))]
    got = dict(zip(cloud["id"], cloud["agglomerateSize"]))
    check("particles in the cloud", len(got), len(want))
    wrong = [i for i in range(1, len(want) + 1) if got.get(i) != want[i - 1]]
    check("particles with a wrong agglomerateSize", wrong, [])
    gotId = dict(zip(cloud["id"], cloud["agglomerateId"]))
    wrong = [i for i in range(1, len(wantId) + 1) if gotId.get(i) != wantId[i - 1]]
    check("particles with a wrong agglomerateId", wrong, [])
    checkCellFields(case, check)

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
