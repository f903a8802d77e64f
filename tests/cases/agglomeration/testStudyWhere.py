#!/usr/bin/env python3
"""Where the study's report finds the agglomerates (studyReport.py,
agglomerates()): a hand-built particle cloud in the slot coater's geometry
(system/slotCoaterParameters of the tutorial: gap 50 um, slot 0..100 um,
span 1.25 um), radius 0.15 um (but one of F), every particle but three
marked agglomerated as the run's analysis would:

  A  a pair touching across the periodic span (z 0.1 um and span - 0.2 um),
     under the upstream lip: one agglomerate, centre z wrapped to 1.2 um
  B  a chain of three along x at 0.3 um spacing below the slot, beside a
     particle with agglomerateSize 1 at contact: one agglomerate of three
  C  a pair in the slot, above the lips
  D  two pairs under the downstream lip, 2 % of a radius apart (beyond the
     agglomerate gap of 1 %, constant/couplingProperties): two
     agglomerates, not one
  E  a chain of four along z, 1 nm apart (touching: below 1 % of R =
     1.5 nm; z 0.2 ... 1.103 um), wider than half the span: centre z
     0.6515 um; its end particles face each other across the periodic
     face 47 nm apart (1.25 - 0.903 - 0.3 um)
  F  a particle of radius R and one of 1.5 R, 2 nm apart (touching would be
     below 1 % of the smaller radius, 1.5 nm: not touching), neither
     marked agglomerated

Then, with a release gap of 2.5 % (a contact lasts to 3.75 nm), a later
write of D, F and G, a pair 2.5 nm apart marked as an agglomerate of 2:
G one agglomerate and not a pair held apart, D still two.  And a third
write with the run's agglomerateId: H, four particles in a row 2.7, 2.5
and 2.8 nm apart (all within the release gap), marked as two agglomerates
of 2, the first two and the last two: two agglomerates, and the middle
pair held apart (grouped by the gaps alone, the closest pair, the middle
one, would be taken as the contact); and I, the two ends of a chain of
three whose middle particle the cloud does not hold (outside the fluid
mesh): one agglomerate, centred between the two.

Expected (by construction): 6 agglomerates with these members, centres
(to 1e-12 m) and parts of the die; three pairs within 50 nm not
touching (F, 2 nm apart, D's middle pair, 3 nm, and E's ends, 47 nm: the
report's close pairs).

usage: testStudyWhere.py colloidFoamDir workDir
"""
import os
import shutil
import sys

import handBuiltCloud

R = 0.15e-6


def write_cloud(time_dir, parts, radius):
    """The particle cloud of a write time (handBuiltCloud.py) with this
    test's radius R"""
    handBuiltCloud.write_cloud(time_dir, parts, radius, R)


def main():
    root, work = sys.argv[1:3]
    sys.path.insert(0, os.path.join(root, "src", "python"))
    sys.path.insert(0, os.path.join(root, "tutorials", "slotCoater"))
    import studyReport

    shutil.rmtree(work, ignore_errors=True)
    handBuiltCloud.case_folder(root, work)
    span = studyReport.geometry(work)["span"]
    u = 1e-6
    # (id, x, y, z, agglomerateSize)
    parts = [(1, -10*u, 1*u, 0.1*u, 2), (2, -10*u, 1*u, span - 0.2*u, 2),               # A
             (3, 50*u, 0.5*u, 0.5*u, 3), (4, 50.3*u, 0.5*u, 0.5*u, 3),
             (5, 50.6*u, 0.5*u, 0.5*u, 3), (6, 50.9*u, 0.5*u, 0.5*u, 1),               # B
             (7, 20*u, 60*u, 0.6*u, 2), (8, 20*u, 60.3*u, 0.6*u, 2),                   # C
             (9, 120*u, 2*u, 0.3*u, 2), (10, 120.3*u, 2*u, 0.3*u, 2),
             (11, 120.6*u + 0.02*R, 2*u, 0.3*u, 2), (12, 120.9*u + 0.02*R, 2*u, 0.3*u, 2),  # D
             (13, 80*u, 5*u, 0.2*u, 4), (14, 80*u, 5*u, 0.501*u, 4),
             (15, 80*u, 5*u, 0.802*u, 4), (16, 80*u, 5*u, 1.103*u, 4),
             (17, 140*u, 3*u, 0.6*u, 1), (18, 140*u + 2.5*R + 2e-9, 3*u, 0.6*u, 1)]     # F
    radius = {18: 1.5*R}                      # E
    write_cloud(os.path.join(work, "1e-05"), parts, radius)

    t, found = studyReport.agglomerates(work)
    expected = [([1, 2], (-10*u, 1*u, (0.1*u + span - 0.2*u - span)/2 % span),
                 "under the upstream lip"),
                ([7, 8], (20*u, 60.15*u, 0.6*u), "in the slot"),
                ([3, 4, 5], (50.3*u, 0.5*u, 0.5*u), "below the slot"),
                ([13, 14, 15, 16], (80*u, 5*u, 0.6515*u), "below the slot"),
                ([9, 10], (120.15*u, 2*u, 0.3*u), "under the downstream lip"),
                ([11, 12], (120.75*u + 0.02*R, 2*u, 0.3*u), "under the downstream lip")]
    ok = abs(t - 1e-5) < 1e-15 and len(found) == len(expected)
    print("write time %g, %d agglomerates (expected %d)" % (t, len(found), len(expected)))
    for ids, c, part in expected:
        match = [f for f in found if f[0] == ids]
        good = len(match) == 1 and match[0][2] == part and \
            all(abs(match[0][1][j] - c[j]) < 1e-12 for j in range(3))
        print("%s: %s at %s: %s" % (ids, part, ["%.4g" % x for x in c],
                                     "ok" if good else "FAIL (found %s)" % match))
        ok = ok and good
    # the pairs held near contact (close_pairs): within 50 nm and not
    # touching, F (2 nm: beyond 1 % of the smaller radius, 1.5 nm), D's
    # middle pair (0.02 R = 3 nm) and E's ends across the periodic face
    # (47 nm); every other pair within 50 nm touches (gap 0 or E's 1 nm),
    # B's fourth included
    counts, closest = studyReport.close_pairs(work, os.path.join(work, "1e-05"))
    good = counts == [2, 2, 2, 3] and abs(closest - 2e-9) < 1e-15
    print("pairs not touching within 5, 10, 20, 50 nm: %s, closest %.4g nm (expected "
          "[2, 2, 2, 3], 2 nm): %s" % (counts, closest*1e9,
                                          "ok" if good else "FAIL"))
    ok = ok and good

    # the counts of each write kept in the case: read back, not computed
    # again (a row changed by hand comes back changed), and computed again
    # when the touching gap differs from the one they were counted with
    times, series, _ = studyReport.close_pair_series(work)
    kept = os.path.join(work, "postProcessing", "closePairs", "closePairs.csv")
    with open(kept) as f:
        lines = f.read().splitlines()
    good = times == [1e-5] and series == [[2, 2, 2, 3]] and len(lines) == 3
    with open(kept, "w") as f:
        f.write("\n".join(lines[:2] + [lines[2].rsplit(",", 1)[0] + ",99"]) + "\n")
    good = good and studyReport.close_pair_series(work)[1] == [[2, 2, 2, 99]]
    with open(os.path.join(work, "constant", "couplingProperties"), "w") as f:
        f.write("contactAnalysis\n{\n    agglomerateGap 0.025;\n}\n")
    # 2.5 % of R (3.75 nm): D's middle pair (3 nm) and F (2 nm) touch
    good = good and studyReport.close_pair_series(work)[1] == [[0, 0, 0, 1]]
    print("close pairs kept in %s, reused, counted again for another touching gap: %s"
          % (os.path.relpath(kept, work), "ok" if good else "FAIL"))
    ok = ok and good

    # a contact held by the release gap (touching below 1 %, released at
    # 2.5 % of R = 3.75 nm): a later write with D and F as above and G, a
    # pair 2.5 nm apart, both marked in an agglomerate of 2 (a contact that
    # formed and is held). G is one agglomerate and not a pair held apart;
    # D's pairs, 3 nm apart but each already an agglomerate of 2, stay two
    # agglomerates and a pair held apart, as does F.
    with open(os.path.join(work, "constant", "couplingProperties"), "w") as f:
        f.write("contactAnalysis\n{\n    touchingGap 0.01;\n    releaseGap 0.025;\n}\n")
    later = [p for p in parts if p[0] in (9, 10, 11, 12, 17, 18)]
    later += [(19, 60*u, 0.5*u, 0.3*u, 2), (20, 60*u + 2*R + 2.5e-9, 0.5*u, 0.3*u, 2)]   # G
    write_cloud(os.path.join(work, "2e-05"), later, radius)
    t, found = studyReport.agglomerates(work)
    counts, closest = studyReport.close_pairs(work, os.path.join(work, "2e-05"))
    good = abs(t - 2e-5) < 1e-15 and sorted(f[0] for f in found) == [[9, 10], [11, 12], [19, 20]] \
        and counts == [2, 2, 2, 2] and abs(closest - 2e-9) < 1e-15
    print("release gap 2.5 %%: agglomerates %s (expected [9, 10], [11, 12], [19, 20]); pairs not "
          "touching within 5, 10, 20, 50 nm: %s, closest %.4g nm (expected [2, 2, 2, 2], 2 nm): %s"
          % (sorted(f[0] for f in found), counts, closest*1e9, "ok" if good else "FAIL"))
    ok = ok and good

    # the run's agglomerateId: H, 21-22 2.7 nm, 22-23 2.5 nm, 23-24 2.8 nm
    # apart, agglomerates (21, 22) and (23, 24)
    x = [70*u]
    for gap in (2.7e-9, 2.5e-9, 2.8e-9):
        x.append(x[-1] + 2*R + gap)
    # I: 25 and 27 of an agglomerate of three, 26 between them not written
    x += [80*u, 80*u + 4*R]
    write_cloud(os.path.join(work, "3e-05"),
                [(21 + k, x[k], 0.5*u, 0.3*u, 2, 21 if k < 2 else 23) for k in range(4)]
                + [(25, x[4], 0.5*u, 0.3*u, 3, 25), (27, x[5], 0.5*u, 0.3*u, 3, 25)], {})
    t, found = studyReport.agglomerates(work)
    counts, closest = studyReport.close_pairs(work, os.path.join(work, "3e-05"))
    centre = {21: (x[0] + x[1])/2, 23: (x[2] + x[3])/2, 25: 80*u + 2*R}
    good = abs(t - 3e-5) < 1e-15 \
        and sorted(f[0] for f in found) == [[21, 22], [23, 24], [25, 27]] \
        and all(abs(f[1][0] - centre[f[0][0]]) < 1e-12 for f in found) \
        and counts == [1, 1, 1, 1] and abs(closest - 2.5e-9) < 1e-15
    print("agglomerateId: agglomerates %s (expected [21, 22], [23, 24], [25, 27] centred at "
          "x %s um); pairs not touching within 5, 10, 20, 50 nm: %s, closest %.4g nm "
          "(expected [1, 1, 1, 1], 2.5 nm): %s"
          % (sorted(f[0] for f in found), sorted("%.6g" % (c*1e6) for c in centre.values()),
             counts, closest*1e9, "ok" if good else "FAIL"))
    ok = ok and good
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
