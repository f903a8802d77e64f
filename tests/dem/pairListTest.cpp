/*---------------------------------------------------------------------------*\
    colloidFoam DEM tests: the colloid pair style's neighbour list, trimmed
    to the colloid forces' range (fix_colloid_pair_list.h).

    trimKeepsHistoryWithItsPair: one row compacted by trimNeighbourRow
        against the row kept by hand (contact flags and history values go
        with their neighbour).
    listHoldsEveryPairInRange: 600 polydisperse spheres (radii 0.1-0.2 um)
        flying apart and into each other, colloid vdW, double layer and
        lubrication (range 0.05 um, skin 0.03 um), 400 steps of one step
        each, in a closed box and in a periodic one.  At every step every pair closer than the range is listed
        (else its forces are lost), and at every step the list was built
        the list is exactly the pairs within max(range, skin/2) + skin,
        counted by brute force over the atoms of the rank (local and
        ghost).  Serial, and on 2 ranks (processors 2 1 1) by the ctest
        dem.pairList.listHoldsEveryPairInRange.2ranks.
    untrimmedWithDelay: with "neigh_modify delay 10" the list is LIGGGHTS'
        own (every pair within f (Ri + Rj) + skin).
    contactHistorySurvivesTrim: a sliding contact (tangential history) of
        two spheres with four resting spheres around the contact line at a
        gap of 0.1 um (listed by LIGGGHTS, beyond the kept gap 0.08 um and
        every force), the list rebuilt at every step: the pair's forces and
        torques must be those of the same pair alone (within 1e-12, relative
        where above 1 nN or nN um), which fails if the trim leaves the
        contact with a dropped neighbour's history (checked by moving the
        history values out of step: the lower spheres precede sphere 2 in
        sphere 1's row).
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include "colloid_neighbour_trim.h"

#include "atom.h"
#include "force.h"
#include "lammps.h"
#include "lmptype.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

using namespace demTest;

namespace
{

const double range = 0.05;      // um, all three outer cut-offs
const double skin = 0.03;       // um
const double keptGap = std::max(range, 0.5*skin) + skin;

// the colloid pair style of the tests (micro units; Walton-Braun contact
// with tangential history; cohesion: the colloid terms, e.g. colloid/vdw/dl)
std::string colloidPairStyle(const std::string& boundary, const std::string& cohesion)
{
    std::ostringstream in;
    in << LiggghtsRun::header(3, boundary)
       << LiggghtsRun::waltonBraunMaterials()
       << "fix c1 all property/global hamakerConstant peratomtypepair 2 1e-5 1e-5 1e-5 1e-5\n"
          "fix c2 all property/global vdwOuterCutoff scalar " << range << "\n"
          "fix c4 all property/global zetaPotential peratomtype -0.03 -0.03\n"
          "fix c5 all property/global saltConcentration scalar 1\n"
          "fix c6 all property/global saltValence scalar 1\n"
          "fix c7 all property/global liquidTemperature scalar 298.15\n"
          "fix c8 all property/global relativePermittivity scalar 78.4\n"
          "fix c10 all property/global doubleLayerOuterCutoff scalar " << range << "\n"
          "fix l1 all property/global liquidViscosity scalar 1\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << range << "\n"
          "neighbor " << skin << " bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion " << cohesion << "\n"
          "pair_coeff * *\n"
          "timestep 1e-4\n";
    return in.str();
}

typedef std::pair<int, int> TagPair;

TagPair tagPair(int a, int b) { return a < b ? TagPair(a, b) : TagPair(b, a); }

// What this rank's pair list holds against the pairs a brute-force search
// over its atoms finds, summed over the ranks
struct ListCheck
{
    long missingInRange = 0;    // pairs closer than the range, not listed
    long listed = 0;            // listed pairs
    long expected = 0;          // pairs within keptGap
    long mismatched = 0;        // listed xor within keptGap
    long liggghtsReach = 0;     // pairs within LIGGGHTS' own list's reach
};

ListCheck checkList(LAMMPS_NS::LAMMPS* lmp)
{
    LAMMPS_NS::Atom* atom = lmp->atom;
    LAMMPS_NS::NeighList* list = lmp->force->pair->list;
    const double factor = lmp->neighbor->contactDistanceFactor;

    std::set<TagPair> listed;
    for (int ii = 0; ii < list->inum; ii++)
    {
        const int i = list->ilist[ii];
        for (int jj = 0; jj < list->numneigh[i]; jj++)
        {
            const int j = list->firstneigh[i][jj] & NEIGHMASK;
            listed.insert(tagPair(atom->tag[i], atom->tag[j]));
        }
    }

    // newton off: a pair of local atoms once, a local atom with a ghost
    // on this rank (and the ghost's owner)
    ListCheck c;
    std::set<TagPair> expected;
    const int nAll = atom->nlocal + atom->nghost;
    for (int i = 0; i < atom->nlocal; i++)
    {
        for (int j = 0; j < nAll; j++)
        {
            if (j == i || (j < atom->nlocal && j < i)) continue;
            const double* xi = atom->x[i];
            const double* xj = atom->x[j];
            const double r = std::sqrt((xi[0] - xj[0])*(xi[0] - xj[0])
                + (xi[1] - xj[1])*(xi[1] - xj[1]) + (xi[2] - xj[2])*(xi[2] - xj[2]));
            const double rSum = atom->radius[i] + atom->radius[j];
            const TagPair key = tagPair(atom->tag[i], atom->tag[j]);
            if (r - rSum < range && !listed.count(key)) c.missingInRange++;
            if (r - rSum <= keptGap) expected.insert(key);
            if (r <= factor*rSum + skin) c.liggghtsReach++;
        }
    }
    for (const TagPair& p : listed) if (!expected.count(p)) c.mismatched++;
    for (const TagPair& p : expected) if (!listed.count(p)) c.mismatched++;
    c.listed = static_cast<long>(listed.size());
    c.expected = static_cast<long>(expected.size());

    long local[5] = {c.missingInRange, c.listed, c.expected, c.mismatched, c.liggghtsReach};
    long all[5];
    MPI_Allreduce(local, all, 5, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    c.missingInRange = all[0];
    c.listed = all[1];
    c.expected = all[2];
    c.mismatched = all[3];
    c.liggghtsReach = all[4];
    return c;
}

} // namespace


TEST(pairList, trimKeepsHistoryWithItsPair)
{
    // six neighbours, two history values each; keep the odd entries
    int jlist[6] = {10, 11, 12, 13, 14, 15};
    int flags[6] = {0, 1, 0, 2, 0, 3};
    double history[12] = {0, 0, 1.5, -1.5, 0, 0, 2.5, -2.5, 0, 0, 3.5, -3.5};
    const int kept = Colloid::trimNeighbourRow(jlist, flags, history, 2, 6,
        [](int j) { return j % 2 == 1; });

    ASSERT_EQ(kept, 3);
    const int jKept[3] = {11, 13, 15};
    const int flagsKept[3] = {1, 2, 3};
    const double historyKept[6] = {1.5, -1.5, 2.5, -2.5, 3.5, -3.5};
    for (int k = 0; k < 3; k++)
    {
        EXPECT_EQ(jlist[k], jKept[k]);
        EXPECT_EQ(flags[k], flagsKept[k]);
        EXPECT_EQ(history[2*k], historyKept[2*k]);
        EXPECT_EQ(history[2*k + 1], historyKept[2*k + 1]);
    }
}


namespace
{

// 600 spheres (radii 0.1-0.2 um) at least 2 nm apart, velocities up to 2
// m/s per component, in the box [-3, 3]^3 (LiggghtsRun::header(3)):
// periodic, anywhere in it (gaps by the nearest image); else in [-2.4,
// 2.4]^3, where they stay over 400 steps (at most 0.14 um).  Input lines.
std::string randomSuspension(bool periodic)
{
    std::mt19937 random(20261206);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double half = periodic ? 3.0 : 2.4;
    auto image = [&](double d) { return periodic ? d - 6.0*std::round(d/6.0) : d; };
    std::vector<double> xs, rs;
    while (rs.size() < 600)
    {
        const double r = 0.1 + 0.1*unit(random);
        const double p[3] = {half*(2*unit(random) - 1), half*(2*unit(random) - 1), half*(2*unit(random) - 1)};
        bool clear = true;
        for (std::size_t k = 0; k < rs.size() && clear; k++)
        {
            const double dx = image(p[0] - xs[3*k]), dy = image(p[1] - xs[3*k + 1]), dz = image(p[2] - xs[3*k + 2]);
            clear = std::sqrt(dx*dx + dy*dy + dz*dz) > r + rs[k] + 0.002;
        }
        if (!clear) continue;
        xs.insert(xs.end(), p, p + 3);
        rs.push_back(r);
    }
    std::ostringstream in;
    in.precision(17);
    for (std::size_t k = 0; k < rs.size(); k++)
        in << "create_atoms 1 single " << xs[3*k] << ' ' << xs[3*k + 1] << ' ' << xs[3*k + 2] << " units box\n";
    for (std::size_t k = 0; k < rs.size(); k++)
        in << "set atom " << k + 1 << " diameter " << 2*rs[k] << " density 2.5"
           << " vx " << 4*unit(random) - 2 << " vy " << 4*unit(random) - 2 << " vz " << 4*unit(random) - 2 << "\n";
    return in.str();
}

// The suspension run 400 steps of one step each, its list checked at
// every step
void followList(const std::string& boundary)
{
    SCOPED_TRACE("boundary " + boundary);
    LiggghtsRun run;
    run.commands("processors * 1 1\n" + colloidPairStyle(boundary, "colloid/vdw/dl/lub")
        + "fix integrate all nve/sphere\n" + randomSuspension(boundary[0] == 'p') + "run 0\n");
    ASSERT_EQ(run.nAtoms(), 600);

    int builds = 0;
    long listedAtBuilds = 0, trimmedAtBuilds = 0;
    for (int step = 0; step <= 400; step++)
    {
        if (step > 0) run.commands("run 1 pre no post no\n");
        const ListCheck c = checkList(run.instance());
        ASSERT_EQ(c.missingInRange, 0) << "step " << step;
        if (run.instance()->neighbor->ago != 0) continue;
        builds++;
        EXPECT_EQ(c.mismatched, 0) << "step " << step << ": " << c.listed
            << " pairs listed, " << c.expected << " within " << keptGap << " um";
        listedAtBuilds += c.listed;
        trimmedAtBuilds += c.liggghtsReach - c.listed;
    }
    std::cout << boundary << ": " << builds << " builds; at the builds " << listedAtBuilds
              << " pairs listed, " << trimmedAtBuilds << " trimmed" << std::endl;
    ASSERT_EQ(run.nAtoms(), 600);
    // the scene tests something: lists built, pairs kept and pairs trimmed
    EXPECT_GE(builds, 5);
    EXPECT_GT(listedAtBuilds, 20*builds);
    EXPECT_GT(trimmedAtBuilds, 20*builds);
    // the fix's count is the list's entries (a pair of two ranks on both)
    LAMMPS_NS::NeighList* list = run.instance()->force->pair->list;
    long entries = 0, all = 0;
    for (int ii = 0; ii < list->inum; ii++) entries += list->numneigh[list->ilist[ii]];
    MPI_Allreduce(&entries, &all, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(run.evaluate("f_colloid_pair_list"), all);
}

} // namespace


TEST(pairList, listHoldsEveryPairInRange)
{
    followList("f f f");
    followList("p p p");
}


// LIGGGHTS' default delay of 10 steps lets a particle move more than half
// the skin before a rebuild: the list is left as LIGGGHTS built it
TEST(pairList, untrimmedWithDelay)
{
    LiggghtsRun run;
    run.commands(colloidPairStyle("f f f", "colloid/vdw/dl/lub") + "neigh_modify delay 10\n"
        + "fix integrate all nve/sphere\n" + randomSuspension(false) + "run 0\n");
    const ListCheck c = checkList(run.instance());
    EXPECT_GT(c.liggghtsReach, c.expected);
    EXPECT_EQ(c.listed, c.liggghtsReach);
}


namespace
{

// A sliding contact: sphere 2 pressed 2 nm into sphere 1 (at rest) and
// moved along y at 0.1 m/s (fix move: both prescribed), 3 nm in 300
// steps, below the Coulomb limit, so the tangential force is the spring
// the history has held since the start.  With ring, four resting spheres
// around the contact line at a gap of 0.1 um from both: within LIGGGHTS'
// list (f (Ri + Rj) + skin: a gap of 0.13 um), beyond the kept gap and
// every force.  The list is rebuilt at
// every step.  Returns the force and torque on both spheres after 300
// steps [nN, nN um], and the pairs listed.
std::vector<double> slide(bool ring, double& listed)
{
    LiggghtsRun run;
    std::ostringstream in;
    in.precision(17);
    const double R = 0.15, gap = 0.1, c = 2*R - 0.002;
    in << colloidPairStyle("f f f", "colloid/vdw/dl")
       << "neigh_modify every 1 check no\n"
          "atom_modify sort 0 0\n"
          "create_atoms 1 single 0 0 0 units box\n"
          "create_atoms 1 single " << c << " 0 0 units box\n";
    if (ring)
    {
        // four around the contact line (x = c/2, 45 degrees off the y and
        // z axes; 0.225 um apart): the lower ones lie in neighbour bins
        // before sphere 2's, so they precede it in sphere 1's row (atoms
        // unsorted: sphere 1 first)
        const double d = 2*R + gap, rho = std::sqrt(d*d - c*c/4)/std::sqrt(2.0);
        for (double y : {-rho, rho})
            for (double z : {-rho, rho})
                in << "create_atoms 1 single " << c/2 << ' ' << y << ' ' << z << " units box\n";
    }
    in << "set atom * diameter " << 2*R << " density 2.5\n"
          "group one id 1\n"
          "group two id 2\n"
          "fix hold one move linear 0 0 0\n"
          "fix slide two move linear 0 0.1 0\n"
          "run 300\n";
    run.commands(in.str());
    listed = run.evaluate("f_colloid_pair_list");
    std::vector<double> state;
    LAMMPS_NS::Atom* atom = run.instance()->atom;
    for (int id : {1, 2})
    {
        const double* f = run.f(id);
        const double* t = atom->torque[atom->map(id)];
        state.insert(state.end(), f, f + 3);
        state.insert(state.end(), t, t + 3);
    }
    return state;
}

} // namespace


TEST(pairList, contactHistorySurvivesTrim)
{
    double listedAlone = 0, listedInRing = 0;
    const std::vector<double> alone = slide(false, listedAlone);
    const std::vector<double> inRing = slide(true, listedInRing);
    EXPECT_EQ(listedAlone, 1);
    EXPECT_EQ(listedInRing, 1);     // the ring trimmed away
    std::cout << "force on sphere 1 [nN]: " << alone[0] << ' ' << alone[1] << ' ' << alone[2]
              << ", torque [nN um]: " << alone[3] << ' ' << alone[4] << ' ' << alone[5] << std::endl;
    // the tangential spring acted: force along the slide, a tenth of the
    // normal force (the spring of one step's slide gives 1/300 of it)
    EXPECT_GT(std::abs(alone[1]), 0.05*std::abs(alone[0]));
    for (std::size_t k = 0; k < alone.size(); k++)
        EXPECT_NEAR(inRing[k], alone[k], 1e-12*std::max(1.0, std::abs(alone[k]))) << "component " << k;
}


int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    ::testing::InitGoogleTest(&argc, argv);
    const int failed = RUN_ALL_TESTS();
    MPI_Finalize();
    return failed;
}
