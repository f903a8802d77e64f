/*---------------------------------------------------------------------------*\
    colloidFoam DEM test: the contact and agglomerate analysis
    (src/liggghtsColloid/colloid_contact_analysis.h) on hand-built
    arrangements whose contacts and clusters are known by construction,
    serial (the 2-rank and processor-boundary cases run through the coupled
    solver: tests/cases/agglomeration).

    Spheres of radius R = 0.5 um; touching below 1 % of R (gap 5 nm),
    bonded into agglomerates below 5 % (25 nm).

    arrangements: in a box periodic in x,
      - a chain of 5 at gaps of 2 nm:              4 contacts, cluster 5;
      - a ring of 6 (hexagon of side 2R + 2 nm):   6 contacts, cluster 6;
      - two pairs at 2 nm:                         2 contacts, 2 clusters of 2;
      - a chain of 3 across the periodic face:     2 contacts, cluster 3;
      - a pair at 10 nm (bonded, not touching):    0 contacts, cluster 2;
      - two isolated spheres, one flagged as touching a wall.
    Expected: 14 pair contacts, 1 wall contact; particles with 0, 1, 2
    contacts: 4, 8, 10; agglomerates {2: 3, 3: 1, 5: 1, 6: 1}, 6 in all,
    20 particles in them, largest 6; each particle's agglomerate size and
    id (the smallest atom id of its cluster). At the first analysis no
    contact counts as formed.

    passingContactDuration: sphere B moves at 1 um/us past sphere A at
    rest, its path 2R + 2 nm from A's centre; the gap stays below 5 nm for
    |x| < sqrt((2R + 5 nm)^2 - (2R + 2 nm)^2), a contact of 0.15518 us.
    Analysed every 1e-3 us: one contact formed and broken, its duration
    within one analysis interval of the closed form (each end is seen up
    to one interval late).

    durationAcrossRestart: the same pass, with two more spheres that B
    passes in the same way, D on the other side of its path just far
    enough ahead that its contact begins right after the restart, and C
    later; in the middle of the contact with A the histories are saved to
    a file and a new analysis (as a resumed run makes) reads them back:
    A's contact keeps its start, and D's and C's, formed after the
    restart, count as formed: three contacts formed and broken, each
    lasting the closed form within one interval. A file of another number of ranks is
    refused (EINVAL) and a missing one reported (ENOENT).

    waveringContact: sphere B wiggles along the line of centres, its gap
    from A 7 - 6 sin(2 pi t/P) nm (1 to 13 nm), P = 0.1 us, three periods;
    its wall flag follows the same gap. Touching below 5 nm: each period a
    contact forms at phase asin(1/3)/(2 pi); it ends when the gap is back
    at 5 nm without a release gap, at 10 nm (phase 7/12) with releaseGap
    0.02 R. Three pair and three wall contacts formed and ended, each as
    long as its closed form within one interval; while held between 5 and
    10 nm, one contact each and one agglomerate of 2 (bonds only by
    contacts). Then the same across a periodic face, where each atom sees
    the other's image (the pair counted once, both atoms' contacts from
    the history).
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"
#include "colloid_contact_analysis.h"
#include "atom.h"

#include <gtest/gtest.h>

#include <array>
#include <cerrno>
#include <fstream>
#include <cmath>
#include <sstream>
#include <vector>

using namespace demTest;
using LAMMPS_NS::ColloidContactAnalysis;

namespace
{

const double R = 0.5;           // um
const double touch = 0.002;     // gap of a touching pair, um
const double loose = 0.010;     // gap of a bonded, not touching pair, um

typedef std::array<double, 3> Point;

std::string materials()
{
    return
        "fix m1 all property/global youngsModulus peratomtype 1e5 1e5\n"
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3\n"
        "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
        "fix m4 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
        "neighbor 0.1 bin\n"
        "pair_style gran model hertz tangential history\n"
        "pair_coeff * *\n"
        "timestep 1e-4\n";
}

void createAtoms(LiggghtsRun& run, const std::vector<Point>& centres)
{
    std::ostringstream in;
    in.precision(17);
    for (const Point& c : centres)
        in << "create_atoms 1 single " << c[0] << ' ' << c[1] << ' ' << c[2] << " units box\n";
    in << "set atom * diameter " << 2*R << " density 2.5\n";
    run.commands(in.str());
}

ColloidContactAnalysis::Settings settings()
{
    ColloidContactAnalysis::Settings s;
    s.touchingGap = 0.01;
    s.agglomerateGap = 0.05;
    return s;
}

} // namespace

TEST(contactAnalysis, arrangements)
{
    const double a = 2*R + touch;
    std::vector<Point> c;
    std::vector<int> groupOf;   // the arrangement of each atom (ids 1, 2, ...)
    auto add = [&](Point p, int g) { c.push_back(p); groupOf.push_back(g); };
    for (int k = 0; k < 5; k++) add({-6.0 + k*a, -5.0, 0.0}, 0);              // chain of 5
    for (int k = 0; k < 6; k++)                                                 // ring of 6
    {
        const double phi = k*M_PI/3;
        add({3.0 + a*std::cos(phi), 4.0 + a*std::sin(phi), 0.0}, 1);
    }
    add({-6.0, 3.0, 0.0}, 2); add({-6.0 + a, 3.0, 0.0}, 2);                    // pair
    add({-6.0, 6.0, 0.0}, 3); add({-6.0 + a, 6.0, 0.0}, 3);                    // pair
    add({10.0 - a/2, 0.0, 5.0}, 4); add({-10.0 + a/2, 0.0, 5.0}, 4);           // across x = +-10
    add({-10.0 + 1.5*a, 0.0, 5.0}, 4);
    add({3.0, -5.0, 5.0}, 5); add({3.0 + 2*R + loose, -5.0, 5.0}, 5);           // loose pair
    add({6.0, 6.0, -5.0}, 6); add({-2.0, -8.0, 6.0}, 7);                         // isolated

    LiggghtsRun run;
    run.commands(LiggghtsRun::header(10.0, "p f f") + materials());
    createAtoms(run, c);
    ColloidContactAnalysis analysis(run.instance(), settings());
    run.commands("run 0");

    const int n = static_cast<int>(c.size());
    ASSERT_EQ(run.nAtoms(), n);
    std::vector<int> wall(n, 0);
    LAMMPS_NS::LAMMPS* lmp = run.instance();
    for (int i = 0; i < lmp->atom->nlocal; i++) wall[i] = lmp->atom->tag[i] == n ? 1 : 0;
    const ColloidContactAnalysis::Result r = analysis.analyse(0.0, wall.data());

    EXPECT_EQ(r.particles, n);
    EXPECT_EQ(r.pairContacts, 14);
    EXPECT_EQ(r.wallContacts, 1);
    EXPECT_EQ(r.pairFormed, 0);
    EXPECT_EQ(r.wallFormed, 0);
    ASSERT_EQ(r.byContacts.size(), 3u);
    EXPECT_EQ(r.byContacts[0], 4);
    EXPECT_EQ(r.byContacts[1], 8);
    EXPECT_EQ(r.byContacts[2], 10);
    EXPECT_EQ(r.agglomerates, 6);
    EXPECT_EQ(r.agglomerated, 20);
    EXPECT_EQ(r.largest, 6);
    const std::map<long, long> sizes = {{2, 3}, {3, 1}, {5, 1}, {6, 1}};
    EXPECT_EQ(r.agglomerateSizes, sizes);

    // each particle: its arrangement's size, and the arrangement's
    // smallest id (ids follow the creation order)
    const long groupSize[] = {5, 6, 2, 2, 3, 2, 1, 1};
    std::vector<long> firstId(8, 0);
    for (int id = n; id >= 1; id--) firstId[groupOf[id - 1]] = id;
    for (int i = 0; i < lmp->atom->nlocal; i++)
    {
        const int id = lmp->atom->tag[i];
        const int g = groupOf[id - 1];
        EXPECT_EQ(analysis.agglomerateSize()[i], groupSize[g]) << "atom " << id;
        if (groupSize[g] > 1) EXPECT_EQ(analysis.agglomerateId()[i], firstId[g]) << "atom " << id;
    }
}

TEST(contactAnalysis, passingContactDuration)
{
    const double v = 1.0;                   // um/us
    const double offset = 2*R + touch;      // path from A's centre, um
    const double halfWindow = std::sqrt(std::pow(2*R + 0.01*R, 2) - offset*offset);
    const double duration = 2*halfWindow/v;
    const double interval = 1e-3;           // us: 10 steps of 1e-4

    LiggghtsRun run;
    run.commands(LiggghtsRun::header(5.0) + materials());
    createAtoms(run, {{0.0, 0.0, 0.0}, {-0.5, offset, 0.0}});
    run.commands("group mover id 2\nfix move mover move linear 1.0 0 0");
    ColloidContactAnalysis analysis(run.instance(), settings());
    run.commands("run 0");

    long formed = 0, broken = 0;
    std::vector<double> durations;
    for (int k = 0; k <= 1000; k++)
    {
        if (k > 0) run.commands("run 10 pre no post no");
        const ColloidContactAnalysis::Result r = analysis.analyse(k*interval, nullptr);
        formed += r.pairFormed;
        broken += r.pairBroken;
        durations.insert(durations.end(), r.pairDurations.begin(), r.pairDurations.end());
        ASSERT_LE(r.pairContacts, 1);
    }
    EXPECT_EQ(formed, 1);
    EXPECT_EQ(broken, 1);
    ASSERT_EQ(durations.size(), 1u);
    std::printf("contact duration %.6f us, closed form %.6f us\n", durations[0], duration);
    EXPECT_NEAR(durations[0], duration, interval);
}

TEST(contactAnalysis, durationAcrossRestart)
{
    const double v = 1.0;                   // um/us
    const double offset = 2*R + touch;
    const double halfWindow = std::sqrt(std::pow(2*R + 0.01*R, 2) - offset*offset);
    const double duration = 2*halfWindow/v;
    const double interval = 1e-3;           // us: 10 steps of 1e-4
    const int restartAt = 500;              // analyses: B is beside A

    LiggghtsRun run;
    run.commands(LiggghtsRun::header(5.0) + materials());
    // D: its window opens 0.4 ns after the restart (B at x = -0.5 + v t)
    const double xD = restartAt*interval - 0.5 + halfWindow + 0.0004;
    createAtoms(run, {{0.0, 0.0, 0.0}, {-0.5, offset, 0.0}, {1.5, 0.0, 0.0}, {xD, 2*offset, 0.0}});
    run.commands("group mover id 2\nfix move mover move linear 1.0 0 0");
    ColloidContactAnalysis before(run.instance(), settings());
    run.commands("run 0");

    long formed = 0, broken = 0;
    std::vector<double> durations;
    auto add = [&](const ColloidContactAnalysis::Result& r)
    {
        formed += r.pairFormed;
        broken += r.pairBroken;
        durations.insert(durations.end(), r.pairDurations.begin(), r.pairDurations.end());
    };
    for (int k = 0; k <= restartAt; k++)
    {
        if (k > 0) run.commands("run 10 pre no post no");
        add(before.analyse(k*interval, nullptr));
    }
    ASSERT_EQ(formed, 1) << "B is not beside A at the restart";
    ASSERT_EQ(before.saveHistories("contactHistory.test"), 0);

    ColloidContactAnalysis after(run.instance(), settings());
    EXPECT_EQ(after.loadHistories("contactHistory.missing"), ENOENT);
    {
        std::ofstream other("contactHistory.twoRanks");
        other << "colloidContactHistories 1 2\n";
    }
    EXPECT_EQ(after.loadHistories("contactHistory.twoRanks"), EINVAL);
    ASSERT_EQ(after.loadHistories("contactHistory.test"), 0);
    for (int k = restartAt + 1; k <= 2100; k++)
    {
        run.commands("run 10 pre no post no");
        add(after.analyse(k*interval, nullptr));
    }
    EXPECT_EQ(formed, 3);
    EXPECT_EQ(broken, 3);
    ASSERT_EQ(durations.size(), 3u);
    std::printf("contact durations %.6f, %.6f and %.6f us, closed form %.6f us\n",
                durations[0], durations[1], durations[2], duration);
    for (double d : durations) EXPECT_NEAR(d, duration, interval);
}

// The gap of B from A of the wavering pair (waveringContact), um; the
// box periodic in x of length 10
double gapOf(const LiggghtsRun& run)
{
    const double* a = run.x(1);
    const double* b = run.x(2);
    const double dx = b[0] - a[0] - 10.0*std::round((b[0] - a[0])/10.0);
    return std::sqrt(dx*dx + std::pow(b[1] - a[1], 2) + std::pow(b[2] - a[2], 2)) - 2*R;
}

TEST(contactAnalysis, waveringContact)
{
    // B wiggles along the line of centres: gap = g0 - amp sin(2 pi t/P),
    // 1 to 13 nm, three periods. Touching below 5 nm (sin > 1/3), so a
    // contact forms at phase f1 = asin(1/3)/(2 pi) of each period; without
    // a release gap it ends when the gap is back at 5 nm (phase 1/2 - f1),
    // with one of 10 nm (0.02 R) when the gap reaches 10 nm (sin = -1/2,
    // phase 7/12). B's "wall" flag follows the same gaps, so its wall
    // contact does the same. Analysed every 1e-3 us; agglomerate bonds
    // only by contacts (agglomerateGap = touchingGap): while the gap is
    // between 5 and 10 nm and the contact lasts, A and B are one
    // agglomerate with one contact each.
    const double g0 = 0.007, amp = 0.006;   // um
    const double period = 0.1;              // us
    const double interval = 1e-3;           // us: 10 steps of 1e-4
    const double f1 = std::asin(1.0/3)/(2*M_PI);

    for (const bool acrossFace : {false, true})
    for (const double releaseGap : {0.01, 0.02})
    {
        SCOPED_TRACE("releaseGap " + std::to_string(releaseGap) + (acrossFace ? ", across the periodic face" : ""));
        const double end = releaseGap > 0.01 ? 7.0/12 : 0.5 - f1;   // phase
        const double duration = (end - f1)*period;

        LiggghtsRun run;
        // across the face x = -5 = 5: each atom sees the other's image
        const double xA = acrossFace ? 4.6 : 0.0;
        const double xB = xA + 2*R + g0 - (acrossFace ? 10.0 : 0.0);
        run.commands(LiggghtsRun::header(5.0, acrossFace ? "p f f" : "f f f") + materials());
        createAtoms(run, {{xA, 0.0, 0.0}, {xB, 0.0, 0.0}});
        std::ostringstream wiggle;
        wiggle << "group mover id 2\nfix move mover move wiggle " << -amp << " 0 0 " << period;
        run.commands(wiggle.str());
        ColloidContactAnalysis::Settings s;
        s.touchingGap = 0.01;
        s.releaseGap = releaseGap;
        s.agglomerateGap = 0.01;
        ColloidContactAnalysis analysis(run.instance(), s);
        run.commands("run 0");

        long formed = 0, broken = 0, wallFormed = 0, wallBroken = 0, heldChecked = 0;
        std::vector<double> durations, wallDurations;
        for (int k = 0; k <= 300; k++)
        {
            if (k > 0) run.commands("run 10 pre no post no");
            const double gap = gapOf(run);
            std::vector<int> wall(2, 0);
            wall[run.instance()->atom->map(2)] = gap < 0.01*R ? 1 : gap < releaseGap*R ? 2 : 0;
            const ColloidContactAnalysis::Result r = analysis.analyse(k*interval, wall.data());
            formed += r.pairFormed;
            broken += r.pairBroken;
            wallFormed += r.wallFormed;
            wallBroken += r.wallBroken;
            durations.insert(durations.end(), r.pairDurations.begin(), r.pairDurations.end());
            wallDurations.insert(wallDurations.end(), r.wallDurations.begin(), r.wallDurations.end());

            // inside the contact's window (one interval from its ends)
            // and not touching: held by the release gap
            const double phase = std::fmod(k*interval, period)/period;
            if (phase > f1 + interval/period && phase < end - interval/period && gap >= 0.01*R)
            {
                heldChecked++;
                EXPECT_EQ(r.pairContacts, 1) << "t " << k*interval;
                EXPECT_EQ(r.wallContacts, 1) << "t " << k*interval;
                ASSERT_EQ(r.byContacts.size(), 2u) << "t " << k*interval;
                EXPECT_EQ(r.byContacts[1], 2) << "t " << k*interval;
                EXPECT_EQ(r.agglomerates, 1) << "t " << k*interval;
            }
        }
        std::printf("release gap %.2f R%s: %zu contacts, durations %.6f .. %.6f us, closed form "
                    "%.6f us; %ld analyses while held\n", releaseGap,
                    acrossFace ? ", across the periodic face" : "", durations.size(),
                    durations.empty() ? 0.0 : durations.front(),
                    durations.empty() ? 0.0 : durations.back(), duration, heldChecked);
        if (releaseGap > 0.01) EXPECT_GT(heldChecked, 30);
        EXPECT_EQ(formed, 3);
        EXPECT_EQ(broken, 3);
        EXPECT_EQ(wallFormed, 3);
        EXPECT_EQ(wallBroken, 3);
        ASSERT_EQ(durations.size(), 3u);
        ASSERT_EQ(wallDurations.size(), 3u);
        for (double d : durations) EXPECT_NEAR(d, duration, interval);
        for (double d : wallDurations) EXPECT_NEAR(d, duration, interval);
    }
}
