#!/usr/bin/env python3
"""The study report's comparison of a case with its numerical variant
(studyReport.py, write_variants(): results/variants.md), on hand-built
study folders: isoelectric and isoelectricSoftContacts, and stable
without its variant.

At their last common write (10 us), agglomerates (ids; members touching,
marked with the run's agglomerateId):
  isoelectric               (1 2) (3 4 5) (7 8) (9 10)
  isoelectricSoftContacts   (1 2) (3 4)   (7 8 30) (9 40)
so 4 / 4 agglomerates, one of the same particles in both, (1 2), and
three sharing two particles, (1 2), (3 4 5) and (7 8); (9 10) shares only
one particle with (9 40): no pair in common.  Pair contacts
(contacts.csv): the case 0, 3, 0, 6 at 0, 5, 7.5 and 10 us; the variant
0, 5, 1, 6 at 0, 2.5, 5 and 10 us: the common times 0, 5 and 10 us, the
largest difference 2 (at 5 us; 2.5 and 7.5 us are not common: a union
of the times, missing counts taken as 0 or carried forward, would give
5 at 2.5 us).
The variant has one more write, at 20 us (agglomerates (50 51), 9 pair
contacts), which the comparison leaves out: the case has no write there
(its analysis went on to 20 us, 12 contacts, as in a run stopped before
its next write: a difference of 3 there, beyond the write compared).
Run times (log.colloidDEMFoam's ClockTime): 120 and 61 s, of runs to 10
and 20 us (their last writes).  Expected row (by hand):
  | isoelectric | SoftContacts | 10 | 6 / 6 | 2 | 4 / 4 | 1 | 3 | 120 / 61 (runs to 10 / 20 µs) |
and no row for stable; a study without any variant writes no variants.md.

usage: testStudyVariants.py colloidFoamDir workDir
"""
import os
import shutil
import sys

import handBuiltCloud

R = 0.15e-6
u = 1e-6


def write_cloud(time_dir, groups):
    """The particle cloud of a write time: the agglomerates groups and a
    lone particle"""
    parts = []      # id, x, y, z, agglomerateSize, agglomerateId
    for g, ids in enumerate(groups):
        for k, i in enumerate(ids):
            parts.append((i, (10 + 5*g)*u + 2*R*k, 2*u, 0.5*u, len(ids), min(ids)))
    parts.append((99, 140*u, 3*u, 0.5*u, 1, 99))        # a lone particle
    handBuiltCloud.write_cloud(time_dir, parts, {}, R)


def write_case(root, case, writes, contacts, clock):
    """A case folder: the tutorial's parameters, a cloud at each write
    time of writes {time name: agglomerates}, the agglomerates lists of
    ids (each a row of touching particles, each at its own x), the contact
    analysis' pair contacts [(time, count)] and a log with the run's clock
    time [s]"""
    handBuiltCloud.case_folder(root, case)
    for name, groups in writes.items():
        write_cloud(os.path.join(case, name), groups)
    analysis = os.path.join(case, "postProcessing", "contactAnalysis", "0")
    os.makedirs(analysis)
    columns = ("time,particles,pairContacts,wallContacts,pairFormed,pairBroken,wallFormed,"
               "wallBroken,pairFormedPerUs,wallFormedPerUs,meanContacts,with0,with1,with2,"
               "with3orMore,agglomerates,agglomeratedParticles,largestAgglomerate")
    with open(os.path.join(analysis, "contacts.csv"), "w") as f:
        f.write(columns + "\n")
        for t, n in contacts:
            f.write("%g,1000,%d,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n" % (t, n))
    with open(os.path.join(analysis, "contactDurations.csv"), "w") as f:
        f.write("timeEnded,kind,duration\n")
    with open(os.path.join(analysis, "agglomerateSizes.csv"), "w") as f:
        f.write("time,size,count\n")
    with open(os.path.join(case, "log.colloidDEMFoam"), "w") as f:
        f.write("Time = %s\n\nExecutionTime = %g s  ClockTime = %g s\n" % (max(writes, key=float),
                                                                           clock - 1, clock))


def main():
    root, work = sys.argv[1:3]
    sys.path.insert(0, os.path.join(root, "src", "python"))
    sys.path.insert(0, os.path.join(root, "tutorials", "slotCoater"))
    import studyReport

    shutil.rmtree(work, ignore_errors=True)
    study = os.path.join(work, "study")
    write_case(root, os.path.join(study, "isoelectric"),
               {"1e-05": [[1, 2], [3, 4, 5], [7, 8], [9, 10]]},
               [(0, 0), (5e-6, 3), (7.5e-6, 0), (1e-5, 6), (2e-5, 12)], 120)
    write_case(root, os.path.join(study, "isoelectricSoftContacts"),
               {"1e-05": [[1, 2], [3, 4], [7, 8, 30], [9, 40]], "2e-05": [[50, 51]]},
               [(0, 0), (2.5e-6, 5), (5e-6, 1), (1e-5, 6), (2e-5, 9)], 61)
    write_case(root, os.path.join(study, "stable"), {"1e-05": []}, [(0, 0), (1e-5, 0)], 100)

    ok = True
    results = os.path.join(work, "results")
    os.makedirs(results)
    cases = sorted(os.path.join(study, c) for c in os.listdir(study))
    studyReport.write_variants(cases, results)
    with open(os.path.join(results, "variants.md")) as f:
        rows = f.read().splitlines()[2:]
    expected = ["| isoelectric | SoftContacts | 10 | 6 / 6 | 2 | 4 / 4 | 1 | 3 | "
                "120 / 61 (runs to 10 / 20 µs) |"]
    good = rows == expected
    print("variants.md rows:\n  %s\nexpected:\n  %s\n%s" % ("\n  ".join(rows), expected[0],
                                                            "ok" if good else "FAIL"))
    ok = ok and good

    # no variant in the study: no variants.md
    alone = os.path.join(work, "resultsAlone")
    os.makedirs(alone)
    studyReport.write_variants([c for c in cases if not c.endswith("SoftContacts")], alone)
    good = not os.path.exists(os.path.join(alone, "variants.md"))
    print("a study without variants writes no variants.md: %s" % ("ok" if good else "FAIL"))
    ok = ok and good
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
