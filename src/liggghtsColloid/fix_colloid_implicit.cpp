/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: implicit update of the damping forces,
   see fix_colloid_implicit.h.
------------------------------------------------------------------------- */

#include "fix_colloid_implicit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mpi.h>
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "colloid_drag_properties.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const char fixId[] = "colloid_implicit";
const char fixStyle[] = "colloid/implicit";

// relative residual (preconditioned norm) at which the solve stops, and
// the iterations allowed before the run is told it did not converge
const double tolerance = 1e-10;
const int maxIterations = 200;

// Weight of the end-of-step velocity in the drag K (u_f - v): 1/2, the
// trapezoidal rule, second order for the particle's relaxation (backward
// Euler lags it: 1 % at t = tau_S with dt = tau_S/27) and A-stable; the
// coupling keeps K dt/m <= 1, where it does not oscillate. Lubrication is
// stiff (c dt/m* >> 1) and needs backward Euler (weight 1), which damps
// the stiff relative motion in one step instead of reversing it.
const double dragWeight = 0.5;

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

// the block replaced by its inverse (positive definite: mass > 0)
void invert(double *b)
{
    const double xx = b[0], yy = b[1], zz = b[2], xy = b[3], xz = b[4], yz = b[5];
    const double cxx = yy*zz - yz*yz, cxy = xz*yz - xy*zz, cxz = xy*yz - xz*yy;
    const double det = xx*cxx + xy*cxy + xz*cxz;
    b[0] = cxx/det;
    b[1] = (xx*zz - xz*xz)/det;
    b[2] = (xx*yy - xy*xy)/det;
    b[3] = cxy/det;
    b[4] = cxz/det;
    b[5] = (xy*xz - xx*yz)/det;
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
    // appended as Modify::add_fix does it
    if (modify->nfix == modify->maxfix)
    {
        modify->maxfix += 16;
        modify->fix = (Fix **) lmp->memory->srealloc(modify->fix,
            modify->maxfix*sizeof(Fix *), "modify:fix");
        lmp->memory->grow(modify->fmask, modify->maxfix, "modify:fmask");
    }
    modify->fix[modify->nfix] = fix;
    modify->fmask[modify->nfix] = fix->setmask();
    modify->nfix++;
    return fix;
}

/* ---------------------------------------------------------------------- */

FixColloidImplicit::FixColloidImplicit(LAMMPS *lmp, int narg, char **arg)
: Fix(lmp, narg, arg),
  collecting_(false),
  Ksl_(NULL),
  uf_(NULL),
  dragforce_(NULL),
  impulse_(NULL),
  integrated_(0),
  nSolves_(0),
  nIterations_(0),
  maxIterations_(0),
  nNotConverged_(0),
  seconds_(0.0)
{
    comm_forward = 3;
    vector_flag = 1;
    size_vector = 5;
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
    if (Ksl_ && !uf_)
        error->all(FLERR, "colloid/implicit: the per-atom drag coefficient 'Ksl' needs "
                          "the fluid velocity 'uf' (fix property/atom ... uf vector ...)");
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
// the update over dt/2
void FixColloidImplicit::setup(int)
{
    solve(0.5*update->dt, false);
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
        default: return seconds_;
    }
}

/* ---------------------------------------------------------------------- */

void FixColloidImplicit::addPair(int i, int j, double c, const double *n)
{
    PairTerm t = {i, j, c, {n[0], n[1], n[2]}};
    pairs_.push_back(t);
}

void FixColloidImplicit::addWall(int i, double c, const double *n, const double *vWall)
{
    WallTerm t = {i, c, {n[0], n[1], n[2]}, {vWall[0], vWall[1], vWall[2]}};
    walls_.push_back(t);
}

/* ---------------------------------------------------------------------- */

double FixColloidImplicit::dot(const double *a, const double *b, int n) const
{
    double local = 0.0, global = 0.0;
    for (int k = 0; k < n; k++) local += a[k]*b[k];
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, world);
    return global;
}

// q = (M + h R) p on the local atoms; p holds the ghosts' values too
void FixColloidImplicit::multiply(double h, const double *p, double *q) const
{
    const int nlocal = atom->nlocal;
    const double *m = atom->rmass;
    const double *K = Ksl_ ? Ksl_->vector_atom : NULL;
    for (int i = 0; i < nlocal; i++)
    {
        const double d = m[i] + (K ? dragWeight*h*K[i] : 0.0);
        for (int k = 0; k < 3; k++) q[3*i + k] = d*p[3*i + k];
    }
    for (const PairTerm & t : pairs_)
    {
        const double rel = h*t.c*(dot3(t.n, &p[3*t.i]) - dot3(t.n, &p[3*t.j]));
        for (int k = 0; k < 3; k++) q[3*t.i + k] += rel*t.n[k];
        if (t.j < nlocal)
            for (int k = 0; k < 3; k++) q[3*t.j + k] -= rel*t.n[k];
    }
    for (const WallTerm & t : walls_)
    {
        const double rel = h*t.c*dot3(t.n, &p[3*t.i]);
        for (int k = 0; k < 3; k++) q[3*t.i + k] += rel*t.n[k];
    }
}

void FixColloidImplicit::solve(double h, bool accumulateImpulse)
{
    const double start = MPI_Wtime();
    solveSystem(h, accumulateImpulse);
    seconds_ += MPI_Wtime() - start;
}

void FixColloidImplicit::solveSystem(double h, bool accumulateImpulse)
{
    collecting_ = false;
    findDragProperties();
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    int local[2] = {!pairs_.empty() || !walls_.empty(), 0}, any[2] = {0, 0};
    for (int i = 0; i < nlocal && !local[1]; i++) local[1] = !(mask[i] & integrated_);
    MPI_Allreduce(local, any, 2, MPI_INT, MPI_MAX, world);
    if (!any[0] && !Ksl_) return;

    const int n = 3*nlocal;
    double **v = atom->v;
    double **f = atom->f;
    const double *m = atom->rmass;
    const double *K = Ksl_ ? Ksl_->vector_atom : NULL;
    double **uf = uf_ ? uf_->array_atom : NULL;
    double **fd = dragforce_ ? dragforce_->array_atom : NULL;

    x_.assign(n, 0.0);
    r_.resize(n);
    z_.resize(n);
    q_.resize(n);
    p_.resize(3*(atom->nmax > 0 ? atom->nmax : 1));
    block_.assign(6*nlocal, 0.0);

    // residual of the start value x = v' - v = 0: h times the force of
    // the step with every damping term at the current velocities
    for (int i = 0; i < nlocal; i++)
    {
        const double Ki = K ? K[i] : 0.0;
        const double d = m[i] + dragWeight*h*Ki;
        block_[6*i] = block_[6*i + 1] = block_[6*i + 2] = d;
        for (int k = 0; k < 3; k++)
        {
            double F = f[i][k];
            if (K) F += Ki*(uf[i][k] - v[i][k]);
            if (fd) F += fd[i][k];
            r_[3*i + k] = h*F;
        }
    }
    for (const PairTerm & t : pairs_)
    {
        const double rel = h*t.c*(dot3(t.n, v[t.i]) - dot3(t.n, v[t.j]));
        addOuter(&block_[6*t.i], h*t.c, t.n);
        for (int k = 0; k < 3; k++) r_[3*t.i + k] -= rel*t.n[k];
        if (t.j < nlocal)
        {
            addOuter(&block_[6*t.j], h*t.c, t.n);
            for (int k = 0; k < 3; k++) r_[3*t.j + k] += rel*t.n[k];
        }
    }
    for (const WallTerm & t : walls_)
    {
        const double rel = h*t.c*(dot3(t.n, v[t.i]) - dot3(t.n, t.vWall));
        addOuter(&block_[6*t.i], h*t.c, t.n);
        for (int k = 0; k < 3; k++) r_[3*t.i + k] -= rel*t.n[k];
    }
    for (int i = 0; i < nlocal; i++) invert(&block_[6*i]);
    // a particle without integrator keeps its velocity (x_i = 0); its
    // force is that of its start residual with its neighbours' new
    // velocities (below)
    if (any[1]) r0_ = r_;
    for (int i = 0; i < nlocal; i++)
        if (!(mask[i] & integrated_))
            for (int k = 0; k < 6; k++) block_[6*i + k] = 0.0;

    // preconditioned conjugate gradients on (M + h R) x = r
    for (int i = 0; i < nlocal; i++) applyBlock(&block_[6*i], &r_[3*i], &z_[3*i]);
    double rz = dot(r_.data(), z_.data(), n);
    const double rz0 = rz;
    for (int k = 0; k < n; k++) p_[k] = z_[k];
    int iterations = 0;
    while (rz > tolerance*tolerance*rz0 && iterations < maxIterations)
    {
        comm->forward_comm_fix(this);
        multiply(h, p_.data(), q_.data());
        const double alpha = rz/dot(p_.data(), q_.data(), n);
        for (int k = 0; k < n; k++)
        {
            x_[k] += alpha*p_[k];
            r_[k] -= alpha*q_[k];
        }
        for (int i = 0; i < nlocal; i++) applyBlock(&block_[6*i], &r_[3*i], &z_[3*i]);
        const double rzNew = dot(r_.data(), z_.data(), n);
        const double beta = rzNew/rz;
        rz = rzNew;
        for (int k = 0; k < n; k++) p_[k] = z_[k] + beta*p_[k];
        iterations++;
    }
    if (!(rz <= tolerance*tolerance*rz0))
    {
        const double residual = std::sqrt(rz/rz0);
        if (nNotConverged_++ == 0 && comm->me == 0)
        {
            char msg[512];
            std::snprintf(msg, sizeof(msg),
                "colloid/implicit: the implicit update of lubrication and drag "
                "did not converge in %d iterations at step " BIGINT_FORMAT
                " (relative residual %g, wanted %g); the step is taken with it",
                maxIterations, update->ntimestep, residual, tolerance);
            error->warning(FLERR, msg);
        }
    }
    nSolves_++;
    nIterations_ += iterations;
    maxIterations_ = std::max(maxIterations_, iterations);

    // forces on the particles without integrator: r0 - (M + h R) x there
    if (any[1])
    {
        for (int k = 0; k < n; k++) p_[k] = x_[k];
        comm->forward_comm_fix(this);
        multiply(h, p_.data(), q_.data());
        for (int i = 0; i < nlocal; i++)
            if (!(mask[i] & integrated_))
                for (int k = 0; k < 3; k++) f[i][k] = (r0_[3*i + k] - q_[3*i + k])/h;
    }

    // the force whose kick of h gives v' = v + x; the drag impulse the
    // coupling hands to the fluid
    double **impulse = (accumulateImpulse && impulse_ && K) ? impulse_->array_atom : NULL;
    for (int i = 0; i < nlocal; i++)
        for (int k = 0; k < 3; k++)
        {
            if (mask[i] & integrated_) f[i][k] = m[i]*x_[3*i + k]/h;
            if (impulse) impulse[i][k] += h*K[i]*(uf[i][k] - (v[i][k] + dragWeight*x_[3*i + k]));
        }
}

/* ---------------------------------------------------------------------- */

int FixColloidImplicit::pack_comm(int n, int *list, double *buf, int, int *)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) buf[m++] = p_[3*list[i] + k];
    return 3;
}

void FixColloidImplicit::unpack_comm(int n, int first, double *buf)
{
    int m = 0;
    for (int i = first; i < first + n; i++)
        for (int k = 0; k < 3; k++) p_[3*i + k] = buf[m++];
}

double FixColloidImplicit::memory_usage()
{
    return sizeof(PairTerm)*pairs_.capacity() + sizeof(WallTerm)*walls_.capacity()
         + sizeof(double)*(x_.capacity() + r_.capacity() + z_.capacity()
                           + p_.capacity() + q_.capacity() + block_.capacity()
                           + r0_.capacity());
}
