/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: implicit update of the damping forces,
   see fix_colloid_implicit.h.
------------------------------------------------------------------------- */

#include "fix_colloid_implicit.h"
#include "colloid_append_fix.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <mpi.h>
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "fix_property_global.h"
#include "colloid_drag_properties.h"
#include "colloid_units.h"
#include "counterRandom.H"

using namespace LAMMPS_NS;
using namespace FixConst;
using colloid::counterRandom::counterWord;
using colloid::counterRandom::mix64;
using colloid::counterRandom::standardNormal;

namespace {

const char fixId[] = "colloid_implicit";
const char fixStyle[] = "colloid/implicit";

// relative residual (preconditioned norm) at which the solve stops, and
// the iterations allowed before the run is told it did not converge
const double tolerance = 1e-10;
const int maxIterations = 200;

// groups of up to this many particles are solved directly (dense Cholesky
// of at most 12 x 12), larger ones by conjugate gradients (cheaper there:
// a few iterations against (3n)^3/6 operations)
const int maxDense = 4;

// the largest lubricationExplicitRatio accepted: half the budget of each
// particle's sum (fix_colloid_implicit.h), so that two candidates fit
const double maxExplicitRatio = 0.25;

// Weight of the end-of-step velocity in the drag K (u_f - v): 1/2, the
// trapezoidal rule, second order for the particle's relaxation (backward
// Euler lags it: 1 % at t = tau_S with dt = tau_S/27) and A-stable; the
// coupling keeps K dt/m <= 1, where it does not oscillate. Lubrication is
// stiff (c dt/m* >> 1) and needs backward Euler (weight 1), which damps
// the stiff relative motion in one step instead of reversing it.
const double dragWeight = 0.5;

// the coupling's drag callbacks, per LIGGGHTS instance
struct DragCallback
{
    void (*callback)(void *);
    void *context;
};
std::map<const LAMMPS *, DragCallback> &dragCallbacks()
{
    static std::map<const LAMMPS *, DragCallback> callbacks;
    return callbacks;
}

// the instances whose next set-up is the particles' first half kick
std::set<const LAMMPS *> &firstKicks()
{
    static std::set<const LAMMPS *> instances;
    return instances;
}

// symmetric 3x3 block stored as xx yy zz xy xz yz
void addOuter(double *b, double w, const double *n)
{
    b[0] += w*n[0]*n[0];
    b[1] += w*n[1]*n[1];
    b[2] += w*n[2]*n[2];
    b[3] += w*n[0]*n[1];
    b[4] += w*n[0]*n[2];
    b[5] += w*n[1]*n[2];
}

// B = the inverse of the block A (positive definite: mass > 0)
void invert(const double *A, double *B)
{
    const double xx = A[0], yy = A[1], zz = A[2], xy = A[3], xz = A[4], yz = A[5];
    const double cxx = yy*zz - yz*yz, cxy = xz*yz - xy*zz, cxz = xy*yz - xz*yy;
    const double inv = 1/(xx*cxx + xy*cxy + xz*cxz);
    B[0] = cxx*inv;
    B[1] = (xx*zz - xz*xz)*inv;
    B[2] = (xx*yy - xy*xy)*inv;
    B[3] = cxy*inv;
    B[4] = cxz*inv;
    B[5] = (xy*xz - xx*yz)*inv;
}

void applyBlock(const double *b, const double *r, double *z)
{
    z[0] = b[0]*r[0] + b[3]*r[1] + b[4]*r[2];
    z[1] = b[3]*r[0] + b[1]*r[1] + b[5]*r[2];
    z[2] = b[4]*r[0] + b[5]*r[1] + b[2]*r[2];
}

double dot3(const double *a, const double *b)
{
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

}

/* ---------------------------------------------------------------------- */

FixColloidImplicit *FixColloidImplicit::find(LAMMPS *lmp)
{
    Modify *modify = lmp->modify;
    for (int i = 0; i < modify->nfix; i++)
        if (std::strcmp(modify->fix[i]->id, fixId) == 0)
            return dynamic_cast<FixColloidImplicit*>(modify->fix[i]);
    return NULL;
}

FixColloidImplicit *FixColloidImplicit::attach(LAMMPS *lmp)
{
    Modify *modify = lmp->modify;
    FixColloidImplicit *fix = find(lmp);
    if (fix && modify->fix[modify->nfix - 1] == fix) return fix;

    // Last in the list: its setup() must follow the walls' (post_force).
    // Moving it in place would break the fix indices that Atom keeps for
    // its per-atom callbacks; Modify::delete_fix updates them, and this
    // fix keeps no state between runs (the models look it up at init).
    if (fix) modify->delete_fix(fixId);
    char id[sizeof(fixId)], group[] = "all", style[sizeof(fixStyle)];
    std::strcpy(id, fixId);
    std::strcpy(style, fixStyle);
    char *arg[3] = {id, group, style};
    fix = new FixColloidImplicit(lmp, 3, arg);
    Colloid::colloidAppendFix(lmp, fix);
    return fix;
}

void FixColloidImplicit::setDragCallback(LAMMPS *lmp, void (*callback)(void *), void *context)
{
    if (callback) dragCallbacks()[lmp] = DragCallback{callback, context};
    else dragCallbacks().erase(lmp);
}

void FixColloidImplicit::setFirstKick(LAMMPS *lmp, bool on)
{
    if (on) firstKicks().insert(lmp);
    else firstKicks().erase(lmp);
}

/* ---------------------------------------------------------------------- */

FixColloidImplicit::FixColloidImplicit(LAMMPS *lmp, int narg, char **arg)
: Fix(lmp, narg, arg),
  collecting_(false),
  h_(0.0),
  Ksl_(NULL),
  uf_(NULL),
  dragforce_(NULL),
  impulse_(NULL),
  assigned_(NULL),
  integrated_(0),
  kT_(0.0),
  seed_(0),
  explicitRatio_(0.0),
  anyExplicit_(false),
  commVectors_(true),
  commWeakSum_(false),
  nSolves_(0),
  nIterations_(0),
  maxIterations_(0),
  nNotConverged_(0),
  seconds_(0.0),
  nGlobalMembers_(0.0),
  nPairsSeen_(0.0),
  nPairsExplicit_(0.0)
{
    comm_forward = 4;       // the liquid's velocity and the weak pairs' sum together
    vector_flag = 1;
    size_vector = 7;
    global_freq = 1;
    extvector = 0;
}

int FixColloidImplicit::setmask()
{
    return PRE_FORCE | PRE_FINAL_INTEGRATE;
}

void FixColloidImplicit::init()
{
    if (force->newton_pair)
        error->all(FLERR, "colloid/implicit (the implicit update of lubrication and drag) "
                          "needs 'newton off': a pair across a processor boundary must be "
                          "on both ranks' neighbour lists");
    if (!atom->rmass_flag)
        error->all(FLERR, "colloid/implicit needs per-particle masses (atom_style granular)");
    findDragProperties();
    findBrownianMotion();
    findExplicitRatio();
    // the particles whose velocity an integrator updates; the others (a
    // fixed bed, say) keep theirs and act on their neighbours like walls
    integrated_ = 0;
    for (int i = 0; i < modify->nfix; i++)
        if (modify->fix[i]->time_integrate) integrated_ |= modify->fix[i]->groupbit;
    if (Ksl_ && modify->n_fixes_style("couple/cfd/force") > 0)
        error->all(FLERR, "colloid/implicit: a 'fix couple/cfd/force...' applies the drag "
                          "Ksl (uf - v) explicitly, and colloid/implicit applies it "
                          "implicitly: remove the couple/cfd fixes and keep the "
                          "property/atom fixes Ksl, uf and dragforce");
}

void FixColloidImplicit::findDragProperties()
{
    Ksl_ = modify->find_fix_property(colloidDrag::coefficient, "property/atom", "scalar", 0, 0, style, false);
    uf_ = modify->find_fix_property(colloidDrag::fluidVelocity, "property/atom", "vector", 0, 0, style, false);
    dragforce_ = modify->find_fix_property(colloidDrag::explicitForce, "property/atom", "vector", 0, 0, style, false);
    impulse_ = modify->find_fix_property(colloidDrag::impulse, "property/atom", "vector", 0, 0, style, false);
    assigned_ = modify->find_fix_property(colloidDrag::assigned, "property/atom", "scalar", 0, 0, style, false);
    if (Ksl_ && !uf_)
        error->all(FLERR, "colloid/implicit: the per-atom drag coefficient 'Ksl' needs "
                          "the fluid velocity 'uf' (fix property/atom ... uf vector ...)");
}

// the local atoms whose drag the coupling has not set yet (0 without a
// callback: nothing would set it)
int FixColloidImplicit::nWithoutDrag() const
{
    if (!assigned_ || !dragCallbacks().count(lmp)) return 0;
    const double *assigned = assigned_->vector_atom;
    int n = 0;
    for (int i = 0; i < atom->nlocal; i++) n += assigned[i] == 0.0;
    return n;
}

// Brownian motion: the random force of the drag's fluctuation-dissipation
// balance. Over a step h each particle gets the impulse R, each component
// Gaussian with variance 2 K k_B T h. With the trapezoidal drag of the
// update, m (w' - w) = -K h (w + w')/2 + R for the half-step velocities w
// that move the particles, so that, at any step, <w^2> = k_B T/m per
// component (the stationary variance of the recursion) and the
// displacement over many steps is the sum of R/K: the diffusion
// coefficient k_B T/K exactly. The written velocity (mean of two
// half-step ones) has the variance k_B T/(m (1 + K h/(2 m))).
// Lubrication has its own noise: each lubricated pair (resistance c,
// normal n) gets the impulses +xi n and -xi n, xi Gaussian with variance
// 2 c k_B T h, so that the noise of all terms has the covariance
// 2 k_B T h times the whole resistance matrix (fluctuation-dissipation
// for the pairs too). With the backward-Euler lubrication the relative
// motion of a pair then diffuses with k_B T over its resistance exactly
// at any step (the displacement over many steps is the sum of the
// impulses over the resistance), and its velocity has the equipartition
// variance to first order in c h/m. A lubricated wall contact gives the
// particle xi n alone, with the variance 2 c k_B T h of its resistance.
void FixColloidImplicit::findBrownianMotion()
{
    kT_ = 0.0;
    Fix *T = modify->find_fix_property("brownianTemperature", "property/global", "scalar", 0, 0, style, false);
    if (!T) return;
    const double kelvin = static_cast<FixPropertyGlobal *>(T)->compute_scalar();
    if (!(kelvin >= 0.0 && kelvin < 1e4))
    {
        char msg[256];
        snprintf(msg, sizeof(msg), "colloid/implicit: property brownianTemperature is %g K; "
                 "allowed range: 0 (no Brownian motion) to 1e4 K", kelvin);
        error->all(FLERR, msg);
    }
    Fix *S = modify->find_fix_property("brownianSeed", "property/global", "scalar", 0, 0, style, false);
    const double seed = S ? static_cast<FixPropertyGlobal *>(S)->compute_scalar() : -1.0;
    if (!(seed >= 1.0 && seed < 4.2e9 && seed == std::floor(seed)))
    {
        char msg[256];
        snprintf(msg, sizeof(msg), "colloid/implicit: Brownian motion (brownianTemperature %g K) "
                 "needs property brownianSeed, an integer from 1 to 4.2e9 (it is %g)", kelvin, seed);
        error->all(FLERR, msg);
    }
    const double boltzmann = 1.380649e-23;      // J/K
    kT_ = boltzmann*kelvin/LIGGGHTS::Colloid::MicroUnits::energy;
    seed_ = static_cast<unsigned long>(seed);
}

// The weak pairs' bound (fix_colloid_implicit.h), 0 without the property
void FixColloidImplicit::findExplicitRatio()
{
    explicitRatio_ = 0.0;
    Fix *P = modify->find_fix_property("lubricationExplicitRatio", "property/global", "scalar", 0, 0, style, false);
    if (!P) return;
    const double ratio = static_cast<FixPropertyGlobal *>(P)->compute_scalar();
    if (!(ratio >= 0.0 && ratio <= maxExplicitRatio))
    {
        char msg[256];
        snprintf(msg, sizeof(msg), "colloid/implicit: property lubricationExplicitRatio is %g; "
                 "allowed range: 0 (every lubricated pair in the implicit solve) to %g "
                 "(the largest c dt/m of a pair damped explicitly)", ratio, maxExplicitRatio);
        error->all(FLERR, msg);
    }
    explicitRatio_ = ratio;
}

// A pair weak enough at both ends to be damped explicitly, if the sums of
// both its particles allow it; both particles integrated
bool FixColloidImplicit::weakCandidate(const PairTerm & t, double h) const
{
    const int *mask = atom->mask;
    const double *m = atom->rmass;
    return (mask[t.i] & integrated_) && (mask[t.j] & integrated_)
        && t.c*h <= explicitRatio_*m[t.i] && t.c*h <= explicitRatio_*m[t.j];
}

// The weak pairs whose particles' sums S (weakSum_, ghosts' communicated)
// are within the budget: their damping impulses over the step, from the
// velocities at its start (the same impulse as the implicit residual's at
// x = 0), into explicitImpulse_, and out of pairs_
void FixColloidImplicit::dampWeakPairs(double h, bool flow, bool thermal, uint64_t pairKey)
{
    const int nlocal = atom->nlocal;
    const int *tag = atom->tag;
    double **v = atom->v;
    explicitImpulse_.assign(3*nlocal, 0.0);
    anyExplicit_ = false;
    std::size_t kept = 0;
    for (std::size_t at = 0; at < pairs_.size(); at++)
    {
        const PairTerm & t = pairs_[at];
        if (!weakCandidate(t, h) || weakSum_[t.i] > explicitBudget || weakSum_[t.j] > explicitBudget)
        {
            pairs_[kept++] = t;
            continue;
        }
        double rel = h*t.c*(dot3(t.n, v[t.i]) - dot3(t.n, v[t.j]));
        if (flow && t.flow != 0.0)
            rel -= h*t.c*t.flow*(dot3(t.n, &p_[3*t.i]) - dot3(t.n, &p_[3*t.j]));
        if (thermal) rel -= pairThermalImpulse(pairKey, tag[t.i], tag[t.j], t.c, h);
        for (int k = 0; k < 3; k++) explicitImpulse_[3*t.i + k] -= rel*t.n[k];
        if (t.j < nlocal)
            for (int k = 0; k < 3; k++) explicitImpulse_[3*t.j + k] += rel*t.n[k];
        anyExplicit_ = true;
        nPairsExplicit_++;
    }
    pairs_.resize(kept);
}

// The key of one solve's random numbers of one stream (the atoms' impulses
// or the pairs' noise): a hash of the seed, the stream, the step number and
// the kind of solve, so that a run gives the same numbers on any number of
// ranks and after a restart.  Hashed once a solve: each number then costs
// one hash, of the key and its counter (counterWord).
uint64_t FixColloidImplicit::solveKey(uint64_t stream, double h) const
{
    const uint64_t phase = h < update->dt ? 1 : 0;      // the set-up's half step
    uint64_t key = mix64(seed_ ^ stream);
    key = mix64(key ^ static_cast<uint64_t>(update->ntimestep));
    return mix64(key ^ phase);
}

// The impulse R of atom tag over the step h (drag coefficient K), from the
// counters 4 tag + k of the solve's atom key
void FixColloidImplicit::thermalImpulse(uint64_t key, int tag, double K, double h, double *R) const
{
    const double sigma = std::sqrt(2.0*K*kT_*h);
    const uint64_t counter = 4*static_cast<uint64_t>(static_cast<uint32_t>(tag));
    for (int k = 0; k < 3; k++) R[k] = sigma*standardNormal(counterWord(key, counter + k));
}

// The lubrication noise xi of the pair of atoms a and b over the step h
// (resistance c), from the solve's pair key and a counter of both ids (in
// either order: a pair across ranks draws the same number on both);
// positive xi pushes the two apart. A wall contact: b = -1 - k for the
// atom's k-th wall contact of the step (as 32 bits 2^32 - 1 - k, above
// every id). The ids' word (lo << 32) | hi is hashed into the counter:
// the pairs of one atom would otherwise differ only in their high 32 bits.
double FixColloidImplicit::pairThermalImpulse(uint64_t key, int a, int b, double c, double h) const
{
    const uint64_t lo = static_cast<uint32_t>(std::min(a, b));
    const uint64_t hi = static_cast<uint32_t>(std::max(a, b));
    return std::sqrt(2.0*c*kT_*h)*standardNormal(counterWord(key, mix64((lo << 32) | hi)));
}

/* ---------------------------------------------------------------------- */

void FixColloidImplicit::setup_pre_force(int vflag)
{
    pre_force(vflag);
}

void FixColloidImplicit::pre_force(int)
{
    pairs_.clear();
    walls_.clear();
    collecting_ = true;
}

// Before the first step the forces get half a kick (velocity Verlet):
// the update over dt/2. At a fresh start (the coupling marks it,
// colloidFirstKick) that kick is momentum the particles take from the
// fluid, and its drag impulse goes to the coupling with the steps' (it was
// lost before: 3 % of the particles' momentum in the periodic box of the
// momentum test, dt K/m = 0.055). Any other set-up replaces forces whose
// impulse was counted in full with their step (the first half kick given,
// the second replaced by this one): it counts nothing, or the half would
// be counted twice.
void FixColloidImplicit::setup(int)
{
    solve(0.5*update->dt, update->nsteps > 0 && firstKicks().count(lmp) > 0);
}

void FixColloidImplicit::pre_final_integrate()
{
    solve(update->dt, true);
}

double FixColloidImplicit::compute_vector(int n)
{
    switch (n)
    {
        case 0: return nSolves_;
        case 1: return nSolves_ ? double(nIterations_)/nSolves_ : 0.0;
        case 2: return maxIterations_;
        case 3: return nNotConverged_;
        case 4: return seconds_;
        case 6:
        {
            const double mine[2] = {nPairsSeen_, nPairsExplicit_};
            double all[2] = {0.0, 0.0};
            MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
            return all[0] > 0.0 ? all[1]/all[0] : 0.0;
        }
        default:
        {
            double all = 0.0;
            MPI_Allreduce(&nGlobalMembers_, &all, 1, MPI_DOUBLE, MPI_SUM, world);
            return nSolves_ ? all/nSolves_ : 0.0;
        }
    }
}

/* ---------------------------------------------------------------------- */

void FixColloidImplicit::addPair(int i, int j, double c, const double *n, double flow)
{
    PairTerm t = {i, j, c, {n[0], n[1], n[2]}, flow};
    pairs_.push_back(t);
}

void FixColloidImplicit::addWall(int i, double c, const double *n, const double *vWall)
{
    WallTerm t = {i, c, {n[0], n[1], n[2]}, {vWall[0], vWall[1], vWall[2]}};
    walls_.push_back(t);
}

/* ---------------------------------------------------------------------- */

// q = (M + h R) p on the members, from the diagonal blocks and the
// pairs' coupling -h c n n^T; p holds the ghosts' values too
void FixColloidImplicit::multiply(const std::vector<int> & members, const std::vector<int> & pairs,
                                  const double *p, double *q) const
{
    const int nlocal = atom->nlocal;
    for (int i : members) applyBlock(&blockA_[6*i], &p[3*i], &q[3*i]);
    for (int at : pairs)
    {
        const PairTerm & t = pairs_[at];
        const double ci = t.c*dot3(t.n, &p[3*t.j]), cj = t.c*dot3(t.n, &p[3*t.i]);
        for (int k = 0; k < 3; k++) q[3*t.i + k] -= h_*ci*t.n[k];
        if (t.j < nlocal)
            for (int k = 0; k < 3; k++) q[3*t.j + k] -= h_*cj*t.n[k];
    }
}

double FixColloidImplicit::dot(const std::vector<int> & members, const double *a, const double *b,
                               bool global) const
{
    double local = 0.0, sum = 0.0;
    for (int i : members) local += dot3(&a[3*i], &b[3*i]);
    if (!global) return local;
    MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
    return sum;
}

// Preconditioned conjugate gradients on the members' part of
// (M + h R) x = r (x starting at 0); global: the members of all ranks
// together (every rank calls it), else this rank's group alone. Returns
// the number of iterations.
int FixColloidImplicit::conjugateGradients(const std::vector<int> & members,
                                           const std::vector<int> & pairs, bool global)
{
    for (int i : members)
    {
        applyBlock(&blockInv_[6*i], &r_[3*i], &z_[3*i]);
        for (int k = 0; k < 3; k++) p_[3*i + k] = z_[3*i + k];
    }
    double rz = dot(members, r_.data(), z_.data(), global);
    const double rz0 = rz;
    int iterations = 0;
    while (rz > tolerance*tolerance*rz0 && iterations < maxIterations)
    {
        if (global) comm->forward_comm_fix(this);
        multiply(members, pairs, p_.data(), q_.data());
        const double alpha = rz/dot(members, p_.data(), q_.data(), global);
        for (int i : members)
        {
            for (int k = 3*i; k < 3*i + 3; k++)
            {
                x_[k] += alpha*p_[k];
                r_[k] -= alpha*q_[k];
            }
            applyBlock(&blockInv_[6*i], &r_[3*i], &z_[3*i]);
        }
        const double rzNew = dot(members, r_.data(), z_.data(), global);
        const double beta = rzNew/rz;
        rz = rzNew;
        for (int i : members)
            for (int k = 3*i; k < 3*i + 3; k++) p_[k] = z_[k] + beta*p_[k];
        iterations++;
    }
    if (!(rz <= tolerance*tolerance*rz0) && nNotConverged_++ == 0)
    {
        char msg[512];
        std::snprintf(msg, sizeof(msg),
            "colloid/implicit: the implicit update of lubrication and drag "
            "did not converge in %d iterations at step " BIGINT_FORMAT
            " (relative residual %g, wanted %g); the step is taken with it",
            maxIterations, update->ntimestep, std::sqrt(rz/rz0), tolerance);
        error->warning(FLERR, msg);
    }
    return iterations;
}

// A pair of a local atom i with a ghost j that is a periodic image of
// another atom k of this rank is a pair of own atoms, on the neighbour
// lists of both (newton off), once with the image of each: the copy whose
// atom i has the smaller id is kept, as the pair (i, k) with its normal
// (the geometry of the image), the other dropped. The atom map returns
// the owned atom before its images. Pairs with atoms of other ranks, and
// any pair in a run without an atom map, stay as they are.
void FixColloidImplicit::foldPeriodicImages()
{
    if (!atom->map_style) return;
    const int nlocal = atom->nlocal;
    const int *tag = atom->tag;
    std::size_t kept = 0;
    for (std::size_t at = 0; at < pairs_.size(); at++)
    {
        PairTerm t = pairs_[at];
        if (t.j >= nlocal)
        {
            const int own = atom->map(tag[t.j]);
            if (own >= 0 && own < nlocal && own != t.i)
            {
                if (tag[t.i] > tag[t.j]) continue;
                t.j = own;
            }
        }
        pairs_[kept++] = t;
    }
    pairs_.resize(kept);
}

// Groups of the coupled particles (coupled_: with a pair or wall term)
// by union-find over the pairs: a group with a pair across the rank's
// boundary (ghost partner) joins the one global solve; every other group
// is solved on its own, without communication, in as many iterations as
// it needs (an isolated pair: one to three), and a particle with walls
// only directly by its block.
void FixColloidImplicit::findGroups()
{
    const int nlocal = atom->nlocal;
    parent_.resize(nlocal);
    for (int i : coupled_) parent_[i] = i;
    auto root = [&](int i)
    {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    };
    groupBoundary_.assign(nlocal, 0);
    for (const PairTerm & t : pairs_)
    {
        if (t.j >= nlocal) { groupBoundary_[t.i] = 1; continue; }
        const int a = root(t.i), b = root(t.j);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }
    for (int i : coupled_)
    {
        parent_[i] = root(i);
        if (groupBoundary_[i]) groupBoundary_[parent_[i]] = 1;
    }

    // members and pairs of each group, sorted by the group's root
    groupStart_.assign(nlocal + 1, 0);
    pairStart_.assign(nlocal + 1, 0);
    for (int i : coupled_) groupStart_[parent_[i] + 1]++;
    for (const PairTerm & t : pairs_) pairStart_[parent_[t.i] + 1]++;
    for (int i = 0; i < nlocal; i++)
    {
        groupStart_[i + 1] += groupStart_[i];
        pairStart_[i + 1] += pairStart_[i];
    }
    groupMembers_.resize(coupled_.size());
    groupPairs_.resize(pairs_.size());
    fill_.assign(groupStart_.begin(), groupStart_.end() - 1);
    for (int i : coupled_) groupMembers_[fill_[parent_[i]]++] = i;
    fill_.assign(pairStart_.begin(), pairStart_.end() - 1);
    for (std::size_t at = 0; at < pairs_.size(); at++) groupPairs_[fill_[parent_[pairs_[at].i]]++] = at;

    boundaryMembers_.clear();
    boundaryPairs_.clear();
    for (int i : coupled_)
    {
        if (parent_[i] != i || !groupBoundary_[i]) continue;
        boundaryMembers_.insert(boundaryMembers_.end(), &groupMembers_[groupStart_[i]], &groupMembers_[groupStart_[i + 1]]);
        boundaryPairs_.insert(boundaryPairs_.end(), groupPairs_.begin() + pairStart_[i], groupPairs_.begin() + pairStart_[i + 1]);
    }
}

// An isolated pair (the commonest group) directly: with w = h c and the
// blocks' inverses Bi, Bj,
//   x_j = Bj (r_j + w n (n.x_i)),
//   (A_i - g n n^T) x_i = r_i + w n (n.Bj r_j),  g = w^2 n.Bj n,
// the latter by Sherman-Morrison on Bi. A particle without integrator has
// Bi = 0, so x = 0 there.
void FixColloidImplicit::solvePair(const PairTerm & t)
{
    const double *Bi = &blockInv_[6*t.i], *Bj = &blockInv_[6*t.j];
    const double w = h_*t.c;
    double yj[3], u[3], rhs[3], a[3], b[3];
    applyBlock(Bj, &r_[3*t.j], yj);
    applyBlock(Bj, t.n, u);
    const double g = w*w*dot3(t.n, u), ny = dot3(t.n, yj);
    for (int k = 0; k < 3; k++) rhs[k] = r_[3*t.i + k] + w*ny*t.n[k];
    applyBlock(Bi, rhs, a);
    applyBlock(Bi, t.n, b);
    const double factor = g*dot3(t.n, a)/(1 - g*dot3(t.n, b));
    double *xi = &x_[3*t.i], *xj = &x_[3*t.j];
    for (int k = 0; k < 3; k++) xi[k] = a[k] + factor*b[k];
    const double nx = dot3(t.n, xi);
    for (int k = 0; k < 3; k++) xj[k] = yj[k] + w*nx*u[k];
}

// A small group directly: its dense matrix (M + h R) by Cholesky. A
// particle without integrator keeps x = 0 (its row and column are those
// of the identity, its right-hand side 0).
void FixColloidImplicit::solveDense(const int *members, int n, const int *pairIdx, int nPairs)
{
    const int N = 3*n;
    const int *mask = atom->mask;
    dense_.assign(N*N, 0.0);
    rhs_.resize(N);
    for (int a = 0; a < n; a++)
    {
        const int i = members[a];
        slot_[i] = a;
        const double *A = &blockA_[6*i];
        const double block[3][3] = {{A[0], A[3], A[4]}, {A[3], A[1], A[5]}, {A[4], A[5], A[2]}};
        for (int k = 0; k < 3; k++)
        {
            for (int l = 0; l < 3; l++) dense_[(3*a + k)*N + 3*a + l] = block[k][l];
            rhs_[3*a + k] = r_[3*i + k];
        }
    }
    for (int q = 0; q < nPairs; q++)
    {
        const PairTerm & t = pairs_[pairIdx[q]];
        const int a = slot_[t.i], b = slot_[t.j];
        const double w = h_*t.c;
        for (int k = 0; k < 3; k++)
            for (int l = 0; l < 3; l++)
            {
                dense_[(3*a + k)*N + 3*b + l] -= w*t.n[k]*t.n[l];
                dense_[(3*b + k)*N + 3*a + l] -= w*t.n[k]*t.n[l];
            }
    }
    for (int a = 0; a < n; a++)
    {
        if (mask[members[a]] & integrated_) continue;
        for (int k = 3*a; k < 3*a + 3; k++)
        {
            for (int l = 0; l < N; l++) dense_[k*N + l] = dense_[l*N + k] = 0.0;
            dense_[k*N + k] = 1.0;
            rhs_[k] = 0.0;
        }
    }
    // Cholesky, lower triangle in place, then the two triangular solves
    for (int j = 0; j < N; j++)
    {
        double d = dense_[j*N + j];
        for (int k = 0; k < j; k++) d -= dense_[j*N + k]*dense_[j*N + k];
        d = std::sqrt(d);
        dense_[j*N + j] = d;
        for (int i = j + 1; i < N; i++)
        {
            double e = dense_[i*N + j];
            for (int k = 0; k < j; k++) e -= dense_[i*N + k]*dense_[j*N + k];
            dense_[i*N + j] = e/d;
        }
    }
    for (int i = 0; i < N; i++)
    {
        double e = rhs_[i];
        for (int k = 0; k < i; k++) e -= dense_[i*N + k]*rhs_[k];
        rhs_[i] = e/dense_[i*N + i];
    }
    for (int i = N - 1; i >= 0; i--)
    {
        double e = rhs_[i];
        for (int k = i + 1; k < N; k++) e -= dense_[k*N + i]*rhs_[k];
        rhs_[i] = e/dense_[i*N + i];
    }
    for (int a = 0; a < n; a++)
        for (int k = 0; k < 3; k++) x_[3*members[a] + k] = rhs_[3*a + k];
}

void FixColloidImplicit::solve(double h, bool accumulateImpulse)
{
    const double start = MPI_Wtime();
    solveSystem(h, accumulateImpulse);
    seconds_ += MPI_Wtime() - start;
}

// the drag properties were found at init (the fix is always created
// before Modify's init); their arrays are read here, as they move
void FixColloidImplicit::solveSystem(double h, bool accumulateImpulse)
{
    collecting_ = false;
    foldPeriodicImages();
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    int local[5] = {!pairs_.empty() || !walls_.empty(), 0, nWithoutDrag(), 0, 0}, any[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i < nlocal && !local[1]; i++) local[1] = !(mask[i] & integrated_);
    if (uf_) for (std::size_t at = 0; at < pairs_.size() && !local[3]; at++) local[3] = pairs_[at].flow != 0.0;
    // the weak pairs' candidates: each local atom's sum S of c h/m
    if (explicitRatio_ > 0.0)
    {
        weakSum_.assign(nlocal + atom->nghost, 0.0);
        for (const PairTerm & t : pairs_)
        {
            if (!weakCandidate(t, h)) continue;
            local[4] = 1;
            weakSum_[t.i] += t.c*h/atom->rmass[t.i];
            if (t.j < nlocal) weakSum_[t.j] += t.c*h/atom->rmass[t.j];
        }
    }
    MPI_Allreduce(local, any, 5, MPI_INT, MPI_MAX, world);

    // atoms inserted since the coupling set the drag: it sets theirs now,
    // on every rank (it may communicate), so that they feel the fluid from
    // this step on and not from its next exchange
    if (any[2])
    {
        const DragCallback & hook = dragCallbacks().at(lmp);
        hook.callback(hook.context);
    }

    if (!any[0] && !Ksl_) return;

    h_ = h;
    p_.resize(3*(atom->nmax > 0 ? atom->nmax : 1));
    double **v = atom->v;
    double **f = atom->f;
    const double *m = atom->rmass;
    const double *K = Ksl_ ? Ksl_->vector_atom : NULL;
    double **uf = uf_ ? uf_->array_atom : NULL;
    double **fd = dragforce_ ? dragforce_->array_atom : NULL;
    double **impulse = (accumulateImpulse && impulse_ && K) ? impulse_->array_atom : NULL;
    const int *tag = atom->tag;
    const bool thermal = kT_ > 0.0 && K;

    // the Brownian impulses of every moving particle with drag, in one pass
    // before the solve uses them: a loop of hashes and normal numbers alone
    // runs faster than the same work spread over the loops below
    if (thermal)
    {
        const uint64_t key = solveKey(atomStream, h);
        thermal_.resize(3*nlocal);
        for (int i = 0; i < nlocal; i++)
        {
            if ((mask[i] & integrated_) && K[i] > 0.0) thermalImpulse(key, tag[i], K[i], h, &thermal_[3*i]);
            else for (int k = 0; k < 3; k++) thermal_[3*i + k] = 0.0;
        }
    }

    // the liquid's velocity at every pair partner, ghosts too, for the
    // pairs damped relative to a share of it (p_ is free until the solve),
    // and the weak pairs' sums at ghosts, in one communication
    if (any[3])
        for (int i = 0; i < nlocal; i++)
            for (int k = 0; k < 3; k++) p_[3*i + k] = uf[i][k];
    if (any[3] || any[4])
    {
        commVectors_ = any[3];
        commWeakSum_ = any[4];
        comm->forward_comm_fix(this);
        commVectors_ = true;
        commWeakSum_ = false;
    }
    const uint64_t pairKey = thermal ? solveKey(pairStream, h) : 0;
    anyExplicit_ = false;
    nPairsSeen_ += pairs_.size();
    if (any[4]) dampWeakPairs(h, any[3], thermal, pairKey);

    // the particles with a pair or wall term
    isCoupled_.assign(nlocal, 0);
    for (const PairTerm & t : pairs_)
    {
        isCoupled_[t.i] = 1;
        if (t.j < nlocal) isCoupled_[t.j] = 1;
    }
    for (const WallTerm & t : walls_) isCoupled_[t.i] = 1;
    coupled_.clear();

    // every other particle alone: (m + h K/2) x = h (f + K (u_f - v) + F);
    // without an integrator it keeps v and feels the drag at v. One
    // division a particle: this loop runs over every particle every step
    // (with seven divisions a particle it was a third of the update's own
    // time, perf of the slot-coater study at 2.0e5 particles)
    const double invH = 1.0/h;
    for (int i = 0; i < nlocal; i++)
    {
        if (isCoupled_[i])
        {
            coupled_.push_back(i);
            continue;
        }
        const double Ki = K ? K[i] : 0.0;
        if (Ki == 0.0 && !fd)       // no damping: f stays, with the weak pairs' damping
        {
            if (anyExplicit_)
                for (int k = 0; k < 3; k++) f[i][k] += explicitImpulse_[3*i + k]*invH;
            continue;
        }
        const bool moves = mask[i] & integrated_;
        // 1/(m + h K/2) of a moving particle; 0 keeps v of one without
        // an integrator (its drag at v)
        const double invMass = moves ? 1.0/(m[i] + dragWeight*h*Ki) : 0.0;
        const double scale = moves ? m[i]*invMass : 1.0;
        for (int k = 0; k < 3; k++)
        {
            const double slip = K ? uf[i][k] - v[i][k] : 0.0;
            double F = f[i][k] + Ki*slip;
            if (fd) F += fd[i][k];
            if (thermal) F += thermal_[3*i + k]*invH;
            if (anyExplicit_) F += explicitImpulse_[3*i + k]*invH;
            f[i][k] = scale*F;
            // x = h F/m' : the drag with the trapezoidal weight, and its
            // random part
            if (impulse) impulse[i][k] += h*Ki*(slip - dragWeight*h*F*invMass)
                                        + (thermal ? thermal_[3*i + k] : 0.0);
        }
    }

    x_.resize(3*nlocal);
    r_.resize(3*nlocal);
    z_.resize(3*nlocal);
    q_.resize(3*nlocal);
    blockA_.resize(6*nlocal);
    blockInv_.resize(6*nlocal);

    // residual of the start value x = v' - v = 0: h times the force of
    // the step with every damping term at the current velocities
    for (int i : coupled_)
    {
        const double Ki = K ? K[i] : 0.0;
        const double d = m[i] + dragWeight*h*Ki;
        double *A = &blockA_[6*i];
        A[0] = A[1] = A[2] = d;
        A[3] = A[4] = A[5] = 0.0;
        for (int k = 0; k < 3; k++)
        {
            double F = f[i][k];
            if (K) F += Ki*(uf[i][k] - v[i][k]);
            if (fd) F += fd[i][k];
            r_[3*i + k] = h*F + (thermal ? thermal_[3*i + k] : 0.0)
                        + (anyExplicit_ ? explicitImpulse_[3*i + k] : 0.0);
            x_[3*i + k] = 0.0;
        }
    }
    for (const PairTerm & t : pairs_)
    {
        double rel = h*t.c*(dot3(t.n, v[t.i]) - dot3(t.n, v[t.j]));
        if (any[3] && t.flow != 0.0)
            rel -= h*t.c*t.flow*(dot3(t.n, &p_[3*t.i]) - dot3(t.n, &p_[3*t.j]));
        if (thermal) rel -= pairThermalImpulse(pairKey, tag[t.i], tag[t.j], t.c, h);
        addOuter(&blockA_[6*t.i], h*t.c, t.n);
        for (int k = 0; k < 3; k++) r_[3*t.i + k] -= rel*t.n[k];
        if (t.j < nlocal)
        {
            addOuter(&blockA_[6*t.j], h*t.c, t.n);
            for (int k = 0; k < 3; k++) r_[3*t.j + k] += rel*t.n[k];
        }
    }
    if (thermal) wallsOf_.assign(nlocal, 0);
    for (const WallTerm & t : walls_)
    {
        double rel = h*t.c*(dot3(t.n, v[t.i]) - dot3(t.n, t.vWall));
        if (thermal) rel -= pairThermalImpulse(pairKey, tag[t.i], -1 - wallsOf_[t.i]++, t.c, h);
        addOuter(&blockA_[6*t.i], h*t.c, t.n);
        for (int k = 0; k < 3; k++) r_[3*t.i + k] -= rel*t.n[k];
    }
    // a particle without integrator keeps its velocity (x_i = 0); its
    // force is that of its start residual with its neighbours' new
    // velocities (below)
    for (int i : coupled_)
    {
        double *B = &blockInv_[6*i];
        if (mask[i] & integrated_) invert(&blockA_[6*i], B);
        else for (int k = 0; k < 6; k++) B[k] = 0.0;
    }
    if (any[1]) r0_ = r_;

    findGroups();
    slot_.resize(nlocal);
    int iterations = 0;
    std::vector<int> & members = groupScratch_;
    std::vector<int> & pairs = pairScratch_;
    for (int g : coupled_)
    {
        if (parent_[g] != g || groupBoundary_[g]) continue;
        if (pairStart_[g + 1] == pairStart_[g])
        {
            // walls only: the block is the whole system
            applyBlock(&blockInv_[6*g], &r_[3*g], &x_[3*g]);
            continue;
        }
        if (groupStart_[g + 1] - groupStart_[g] == 2 && pairStart_[g + 1] - pairStart_[g] == 1)
        {
            solvePair(pairs_[groupPairs_[pairStart_[g]]]);
            iterations = std::max(iterations, 1);
            continue;
        }
        const int size = groupStart_[g + 1] - groupStart_[g];
        if (size <= maxDense)
        {
            solveDense(&groupMembers_[groupStart_[g]], size,
                       &groupPairs_[pairStart_[g]], pairStart_[g + 1] - pairStart_[g]);
            iterations = std::max(iterations, 1);
            continue;
        }
        members.assign(&groupMembers_[groupStart_[g]], &groupMembers_[groupStart_[g + 1]]);
        pairs.assign(groupPairs_.begin() + pairStart_[g], groupPairs_.begin() + pairStart_[g + 1]);
        iterations = std::max(iterations, conjugateGradients(members, pairs, false));
    }
    iterations = std::max(iterations, conjugateGradients(boundaryMembers_, boundaryPairs_, true));
    nGlobalMembers_ += boundaryMembers_.size();
    nSolves_++;
    nIterations_ += iterations;
    maxIterations_ = std::max(maxIterations_, iterations);

    // forces on the particles without integrator: r0 - (M + h R) x there
    if (any[1])
    {
        std::vector<int> allPairs(pairs_.size());
        for (std::size_t at = 0; at < pairs_.size(); at++) allPairs[at] = at;
        for (int i : coupled_)
            for (int k = 0; k < 3; k++) p_[3*i + k] = x_[3*i + k];
        comm->forward_comm_fix(this);
        multiply(coupled_, allPairs, p_.data(), q_.data());
        for (int i : coupled_)
            if (!(mask[i] & integrated_))
                for (int k = 0; k < 3; k++) f[i][k] = (r0_[3*i + k] - q_[3*i + k])/h;
    }

    // the force whose kick of h gives v' = v + x; the drag impulse the
    // coupling hands to the fluid
    const double mOverH = 1.0/h;
    for (int i : coupled_)
        for (int k = 0; k < 3; k++)
        {
            if (mask[i] & integrated_) f[i][k] = m[i]*x_[3*i + k]*mOverH;
            if (impulse) impulse[i][k] += h*K[i]*(uf[i][k] - (v[i][k] + dragWeight*x_[3*i + k]))
                                        + (thermal ? thermal_[3*i + k] : 0.0);
        }
}

/* ---------------------------------------------------------------------- */

int FixColloidImplicit::pack_comm(int n, int *list, double *buf, int, int *)
{
    int m = 0;
    for (int i = 0; i < n; i++)
    {
        if (commVectors_)
            for (int k = 0; k < 3; k++) buf[m++] = p_[3*list[i] + k];
        if (commWeakSum_) buf[m++] = weakSum_[list[i]];
    }
    return (commVectors_ ? 3 : 0) + (commWeakSum_ ? 1 : 0);
}

void FixColloidImplicit::unpack_comm(int n, int first, double *buf)
{
    int m = 0;
    for (int i = first; i < first + n; i++)
    {
        if (commVectors_)
            for (int k = 0; k < 3; k++) p_[3*i + k] = buf[m++];
        if (commWeakSum_) weakSum_[i] = buf[m++];
    }
}

double FixColloidImplicit::memory_usage()
{
    return sizeof(PairTerm)*pairs_.capacity() + sizeof(WallTerm)*walls_.capacity()
         + sizeof(double)*(x_.capacity() + r_.capacity() + z_.capacity()
                           + p_.capacity() + q_.capacity() + blockA_.capacity()
                           + blockInv_.capacity() + r0_.capacity() + thermal_.capacity()
                           + weakSum_.capacity() + explicitImpulse_.capacity())
         + sizeof(int)*(parent_.capacity() + groupStart_.capacity() + pairStart_.capacity()
                        + groupMembers_.capacity() + groupPairs_.capacity() + fill_.capacity()
                        + boundaryMembers_.capacity() + boundaryPairs_.capacity()
                        + coupled_.capacity() + groupScratch_.capacity() + pairScratch_.capacity())
         + isCoupled_.capacity() + groupBoundary_.capacity();
}
