#!/usr/bin/env python3
"""The study report's contacts and agglomerates at the seeds' times and on
to the residence time (studyReport.py, write_milestones():
results/milestones.md), and its count of agglomerates by part of the die
and size (where_counts(), the first table of where.md), on hand-built
input.

Contact analyses (postProcessing/contactAnalysis/<start>/contacts.csv):

  isoelectric, resumed: the first part's folder 0 analysed every 10 us to
  70 us, the resumed part's folder 6e-05 from 60 to 130 us (the first
  part's 60 and 70 us are replaced: they hold 100 contacts formed, which
  would show).  Its times carry round-off: 6.0000000000001e-05 and
  1.0999999999999e-04.  Per analysis (time [us]: pair contacts formed,
  ended; after it pair contacts, wall contacts, agglomerates, particles
  in them, largest, particles present):
      10: 1, 0    30: 2, 1    50: 1, 0
      60: 2, 0; 5, 1, 3, 8, 3, 1000
      80: 3, 1    110: 1, 0; 8, 1, 4, 12, 5, 1010
      120: 2, 2   130: 1, 0; 9, 2, 5, 14, 5, 1020
  so (by hand) at 60 us 6 formed and 1 ended since 0 us, 0.1 per us;
  at 110 us 4 and 1 since 60 us, 0.08 per us; its last analysis, 130 us,
  3 and 2 since 110 us, 0.15 per us; 8 of 1000 particles are 0.8 %, 12 of
  1010 1.19 %, 14 of 1020 1.37 %.
  stable: analysed at 0, 25 and 50 us, no contact: one row, its end.
  nearCCC: analysed at 0, 60, 110, 200, 300, 400, 450 and 500 us, one
  contact formed at each: a row at each milestone, 2 formed from 400 to
  500 us (0.02 per us), none more for the end, which is a milestone.
  marginal: analysed at 0, 50 and 150 us only (3 and 2 contacts formed,
  none ended): the 60 and 110 us milestones both fall on the 50 us
  analysis, given once (3 formed, 0.06 per us), then the end, 150 us (2
  formed in 100 us, 0.02 per us).

where_counts: one of 2 particles in the slot, then agglomerates of 2, 3,
4, 5, 9, 10 and 12 particles under the upstream lip, then one of 3 below
the slot: per part of the die in the order upstream lip, below the slot,
downstream lip, in the slot (not the order met), then all: (under the
upstream lip, 7, [1, 1, 1, 2, 2], 45), (below the slot, 1, [0, 1, 0, 0,
0], 3), (in the slot, 1, [1, 0, 0, 0, 0], 2), (all, 9, [2, 2, 1, 2, 2],
50); none: only (all, 0, [0, 0, 0, 0, 0], 0).

usage: testStudyMilestones.py colloidFoamDir workDir
"""
import os
import shutil
import sys

COLUMNS = ("time,particles,pairContacts,wallContacts,pairFormed,pairBroken,wallFormed,"
           "wallBroken,pairFormedPerUs,wallFormedPerUs,meanContacts,with0,with1,with2,"
           "with3orMore,agglomerates,agglomeratedParticles,largestAgglomerate")


def write_analysis(case, start, rows):
    """contacts.csv of the analysis started at start (folder name), rows
    (time [s] as written, formed, ended, pair contacts, wall contacts,
    agglomerates, particles in them, largest, particles present)"""
    folder = os.path.join(case, "postProcessing", "contactAnalysis", start)
    os.makedirs(folder)
    with open(os.path.join(folder, "contacts.csv"), "w") as f:
        f.write("# hand-built (testStudyMilestones.py)\n" + COLUMNS + "\n")
        for t, formed, ended, pairs, walls, n, inside, largest, present in rows:
            f.write("%s,%d,%d,%d,%d,%d,0,0,0,0,0,0,0,0,0,%d,%d,%d\n" % (
                t, present, pairs, walls, formed, ended, n, inside, largest))


def main():
    root, work = sys.argv[1:3]
    sys.path.insert(0, os.path.join(root, "src", "python"))
    sys.path.insert(0, os.path.join(root, "tutorials", "slotCoater"))
    import studyReport

    shutil.rmtree(work, ignore_errors=True)
    study = os.path.join(work, "study")
    iso = os.path.join(study, "isoelectric")
    write_analysis(iso, "0", [
        ("0", 0, 0, 0, 0, 0, 0, 0, 1000), ("1e-05", 1, 0, 1, 0, 1, 2, 2, 1000),
        ("2e-05", 0, 0, 1, 0, 1, 2, 2, 1000), ("3e-05", 2, 1, 2, 0, 2, 4, 2, 1000),
        ("4e-05", 0, 0, 2, 0, 2, 4, 2, 1000), ("5e-05", 1, 0, 3, 0, 2, 5, 3, 1000),
        ("6e-05", 100, 0, 103, 0, 90, 200, 3, 1000), ("7e-05", 100, 0, 203, 0, 90, 200, 3, 1000)])
    write_analysis(iso, "6e-05", [
        ("6.0000000000001e-05", 2, 0, 5, 1, 3, 8, 3, 1000), ("7e-05", 0, 0, 5, 1, 3, 8, 3, 1000),
        ("8e-05", 3, 1, 7, 1, 4, 11, 4, 1010), ("9e-05", 0, 0, 7, 1, 4, 11, 4, 1010),
        ("0.0001", 0, 0, 7, 1, 4, 11, 4, 1010),
        ("1.0999999999999e-04", 1, 0, 8, 1, 4, 12, 5, 1010),
        ("0.00012", 2, 2, 8, 1, 4, 12, 5, 1020), ("0.00013", 1, 0, 9, 2, 5, 14, 5, 1020)])
    write_analysis(os.path.join(study, "stable"), "0", [
        ("0", 0, 0, 0, 0, 0, 0, 0, 1000), ("2.5e-05", 0, 0, 0, 0, 0, 0, 0, 1000),
        ("5e-05", 0, 0, 0, 0, 0, 0, 0, 1000)])
    write_analysis(os.path.join(study, "nearCCC"), "0", [("0", 0, 0, 0, 0, 0, 0, 0, 1000)] + [
        (t, 1, 0, k + 1, 0, k + 1, 2*(k + 1), 2, 1000)
        for k, t in enumerate(("6e-05", "0.00011", "0.0002", "0.0003", "0.0004", "0.00045",
                               "0.0005"))])
    write_analysis(os.path.join(study, "marginal"), "0", [
        ("0", 0, 0, 0, 0, 0, 0, 0, 1000), ("5e-05", 3, 0, 3, 0, 3, 6, 2, 1000),
        ("0.00015", 2, 0, 5, 0, 5, 10, 2, 1000)])

    results = os.path.join(work, "results")
    os.makedirs(results)
    cases = [os.path.join(study, c) for c in ("isoelectric", "stable", "nearCCC", "marginal")]
    studyReport.write_milestones(cases, results)
    with open(os.path.join(results, "milestones.md")) as f:
        rows = f.read().splitlines()[2:]
    expected = ["| isoelectric | 60 | 5 | 1 | 3 | 8 (0.8 %) | 3 | 6 / 1 | 0.1 |",
                "| isoelectric | 110 | 8 | 1 | 4 | 12 (1.19 %) | 5 | 4 / 1 | 0.08 |",
                "| isoelectric | 130 | 9 | 2 | 5 | 14 (1.37 %) | 5 | 3 / 2 | 0.15 |",
                "| stable | 50 | 0 | 0 | 0 | 0 (0 %) | 0 | 0 / 0 | 0 |",
                "| nearCCC | 60 | 1 | 0 | 1 | 2 (0.2 %) | 2 | 1 / 0 | 0.0167 |",
                "| nearCCC | 110 | 2 | 0 | 2 | 4 (0.4 %) | 2 | 1 / 0 | 0.02 |",
                "| nearCCC | 200 | 3 | 0 | 3 | 6 (0.6 %) | 2 | 1 / 0 | 0.0111 |",
                "| nearCCC | 300 | 4 | 0 | 4 | 8 (0.8 %) | 2 | 1 / 0 | 0.01 |",
                "| nearCCC | 400 | 5 | 0 | 5 | 10 (1 %) | 2 | 1 / 0 | 0.01 |",
                "| nearCCC | 500 | 7 | 0 | 7 | 14 (1.4 %) | 2 | 2 / 0 | 0.02 |",
                "| marginal | 50 | 3 | 0 | 3 | 6 (0.6 %) | 2 | 3 / 0 | 0.06 |",
                "| marginal | 150 | 5 | 0 | 5 | 10 (1 %) | 2 | 2 / 0 | 0.02 |"]
    ok = rows == expected
    for k in range(max(len(rows), len(expected))):
        got = rows[k] if k < len(rows) else "(none)"
        want = expected[k] if k < len(expected) else "(none)"
        print("%s\n    expected %s: %s" % (got, want, "ok" if got == want else "FAIL"))

    up, below, slot = "under the upstream lip", "below the slot", "in the slot"
    groups = [([0, 1], (0, 0, 0), slot)]
    groups += [(list(range(n)), (0, 0, 0), up) for n in (2, 3, 4, 5, 9, 10, 12)]
    groups.append(([0, 1, 2], (0, 0, 0), below))
    counts = studyReport.where_counts(groups)
    want = [(up, 7, [1, 1, 1, 2, 2], 45), (below, 1, [0, 1, 0, 0, 0], 3),
            (slot, 1, [1, 0, 0, 0, 0], 2), ("all", 9, [2, 2, 1, 2, 2], 50)]
    good = counts == want
    print("where_counts %s\n    expected %s: %s" % (counts, want, "ok" if good else "FAIL"))
    ok = ok and good
    counts = studyReport.where_counts([])
    good = counts == [("all", 0, [0, 0, 0, 0, 0], 0)]
    print("where_counts of none %s: %s" % (counts, "ok" if good else "FAIL"))
    ok = ok and good
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
