/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: the implicit velocity update of every
   linear damping force of a step - normal lubrication between particles
   and against walls, and the fluid drag K (u_f - v) of the coupling -
   solved together, for all particles at once, by backward Euler.

   Why one solve: a pairwise implicit lubrication force (each pair damped
   with its own reduced mass) adds up the kicks of z neighbours and gains
   energy in clusters once c dt/m* passes about 2/z; an explicit drag
   outside the implicit update biases the overdamped drift by a term of
   order dt/tau_Stokes. Backward Euler on the whole damping matrix R has
   neither problem:
       (M + dt R) v' = M v + dt (f + K u_f)     [drag: see below],
   f: every other force of the step (contact, surface forces, gravity,
   the coupling's explicit drag part), all evaluated before this fix;
   R = sum over lubricated pairs c n n^T (e_i - e_j)(e_i - e_j)^T
       [a pair with a flow factor phi (lubrication.H, the two-sphere
       form) adds c phi n n^T (u_f,i - u_f,j) to i's right-hand side and
       its negative to j's: damping relative to a share of the liquid's
       velocity; the liquid's velocity at a ghost partner comes by one
       forward communication a solve]
     + sum over lubricated wall contacts c n n^T (wall velocity on the right)
     + K (drag). R is symmetric positive semi-definite, so
     - the kinetic energy cannot grow from damping, for any dt and any
       number of neighbours (v'^T M v' <= v'^T M v);
     - a state in force balance (R v = f + K u_f) is kept exactly: the
       quasi-static (overdamped) drift is exact at any step;
     - every pair's damping impulse is equal and opposite (momentum kept).
   The drag takes the trapezoidal rule instead, K (u_f - (v + v')/2):
   second order for a particle's relaxation, A-stable, still exact in
   force balance; the matrix then has K/2 on its diagonal.
   A particle without pair or wall terms is updated alone (a scalar
   division by m + dt K/2). Particles coupled by pairs form groups
   (union-find). A particle with walls only is solved directly by its own
   3x3 block (M + dt R)_ii, an isolated pair directly (Sherman-Morrison),
   a group of up to 4 particles directly (dense Cholesky), every larger
   group
   that lies within the rank by conjugate gradients preconditioned with
   those blocks, on its own and in as many iterations as it needs (an
   isolated pair: one to three); the groups with a partner on another rank
   (or an unfolded periodic image, below) together, in one global solve
   whose ghost search directions come by forward communication. With an
   atom map (atom_modify map array|hash; the coupling sets it), a pair
   with a periodic image of another of the rank's own atoms (a slab
   periodic in a direction the rank is not split in, or any periodic box
   in serial) is folded onto the own atom first:
   such groups are solved on the rank, without communication (each
   iteration of the global solve costs a forward communication of all
   ghosts and two reductions; slot-coater study on 2 ranks, periodic
   span: 237 particles per step in it before, 5.9 after; README). Every
   solve stops at a relative residual of 1e-10 in the preconditioned norm. The result is
   the same serial and parallel (newton off: a pair across a processor
   boundary is on both ranks' lists).

   Particles that no fix integrates (e.g. a fixed bed) keep their
   velocity: they enter the system like walls, and their force is the
   damping at their neighbours' new velocities (what a force output or
   the fluid coupling reads).

   The fix sets each particle's force to M (v' - v)/dt in
   pre_final_integrate, after every post_force fix: the velocity-Verlet
   half kicks of nve/sphere (end of this step, start of the next) then give
   v' at the next position update. LIGGGHTS' fix factory cannot be
   extended from a plugin (Modify::fix_map is private), so the fix is
   created by code, not by a "fix" command: attach() appends it to
   Modify's public fix list the way Modify::add_fix does, and keeps it
   last (re-creating it at the end when fixes were added after it) so
   that its setup() also sees every wall's forces.

   Weak pairs explicitly (property/global lubricationExplicitRatio, a
   scalar from 0 to 0.25; 0 or absent: every pair in the solve): a pair
   whose resistance is weak against both particles' masses, c h/m <= the
   ratio at each end, is damped from the velocities at the start of the
   step, -c n n^T (v_i - v_j - phi (u_f,i - u_f,j)) with its noise, like
   a force, and leaves the solve, provided that the explicit candidates of
   each of its two particles add up to S_i = sum c h/m_i <= 1/2. Why: the
   two-sphere form (lubrication.H) couples every pair within a radius;
   at 5 % solids the particles then form groups that span the domain, and
   the solve of those groups was 40 % of the particle run (slot coater,
   cut-off 0.15 um; README), while most of their pairs are far apart and
   weak. Why it stays stable (the update without forces and noise): with
   L_e the explicit pairs' matrix,
   x^T h L_e x = h sum c (n.(x_i - x_j))^2 <= sum_i 2 S_i m_i |x_i|^2,
   so h L_e <= M when every S_i <= 1/2. The update is A v' = B v with
   A = M + h R_implicit + h K/2 and B = M - h L_e - h K/2 (K: the
   coupling's drag); A - B = h (R_implicit + L_e + K) >= 0 always and
   A + B = 2M + h R_implicit - h L_e >= 0 when h L_e <= M, so B lies
   between -A and A and v^T A v cannot grow, for any number of neighbours,
   any drag and any implicit pairs beside. The kinetic energy cannot grow
   either when also h K/2 <= M (the coupling keeps K h/m <= 1): in the
   mass norm A >= M and B lies between -M and M. The per-pair bound
   keeps the lag of the explicit damping small (its error is of order
   c h/m); a state in force balance is still kept exactly. With Brownian
   noise (property brownianTemperature) the lag shows in the velocities
   (the update's, which move the particles), not in the positions: an
   isolated explicit pair of equal spheres (or without drag) has the
   relative velocity variance kT/(m* (1 - lambda/2)) along its axis,
   lambda = c h/m*, m* = m_i m_j/(m_i + m_j) (+33 % at the ratio 0.25;
   an implicit pair's is kT/(m* (1 + lambda/2)), below), while its
   relative diffusion over many steps is exact (tests: brownian
   lubricatedPairVelocities(Explicit), lubricatedPairDiffusionExplicit).
   Each rank decides a pair from c, both masses and both S (a
   ghost's S by one forward communication, with the liquid's velocity),
   so a pair across ranks is treated alike on both. Pairs with a particle
   that no fix integrates stay in the solve.

   Statistics since the fix was created, as its global vector, e.g.
   "thermo_style custom step f_colloid_implicit[2]": [1] updates, [2] mean
   and [3] largest number of iterations, [4] updates that did not converge
   in 200 iterations (they warn once), [5] wall-clock seconds spent in the
   updates (this rank), [6] particles in the global solve per update (all
   ranks together; 0 in serial with an atom map), [7] the share of the
   lubricated pairs damped explicitly (all ranks, 0 to 1).

   Who attaches it: every pair style with a colloid cohesion model (at its
   init, before Modify's), and the CFD coupling (colloidImplicitUpdate()).
   Lubrication models record (i, j, c, n) during the force computation
   instead of applying a force; the coupling's drag comes from per-atom
   properties (colloid_drag_properties.h). An atom inserted during a run
   has no drag until the coupling sets it; when the coupling has given a
   callback (colloidDragCallback), the solve of the step in which such an
   atom first appears calls it on every rank before it reads the drag, so
   that the particle feels the fluid (drag, gravity, buoyancy) from its
   first step. The check rides on the solve's one MPI_Allreduce.
------------------------------------------------------------------------- */

#ifndef COLLOID_FIX_COLLOID_IMPLICIT_H
#define COLLOID_FIX_COLLOID_IMPLICIT_H

#include <cstdint>
#include <vector>
#include "fix.h"

namespace LAMMPS_NS {

class FixColloidImplicit : public Fix
{
public:
    //- The fix of this LIGGGHTS instance, created if absent or if it is
    //  not the last fix (the old one is deleted: pointers to it become
    //  invalid). Call before Modify::init (e.g. from a pair style's init,
    //  or between runs).
    static FixColloidImplicit *attach(LAMMPS *lmp);

    //- The fix of this instance, or NULL
    static FixColloidImplicit *find(LAMMPS *lmp);

    //- The coupling's hook for atoms without drag (colloidDragSet 0), see
    //  colloidDragCallback in register_colloid_models.h; kept per LIGGGHTS
    //  instance, not in the fix, which attach() may re-create
    static void setDragCallback(LAMMPS *lmp, void (*callback)(void *), void *context);

    //- The coupling's mark of a set-up that is the particles' first half
    //  kick (colloidFirstKick in register_colloid_models.h); kept per
    //  LIGGGHTS instance, as the callback
    static void setFirstKick(LAMMPS *lmp, bool on);

    FixColloidImplicit(LAMMPS *lmp, int narg, char **arg);

    int setmask();
    void init();
    void setup_pre_force(int);
    void pre_force(int);
    void setup(int);
    void pre_final_integrate();
    double compute_vector(int n);
    int pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc);
    void unpack_comm(int n, int first, double *buf);
    double memory_usage();

    //- Whether the models of this step should record their damping here
    //  (false outside the force computation, e.g. for a compute that
    //  re-evaluates the contacts at output)
    bool collecting() const { return collecting_; }

    //- A lubricated pair: local atom i, atom j (local or ghost),
    //  resistance c [run units: mass/time], unit normal n from j to i;
    //  the damping acts on the normal velocity relative to flow times the
    //  liquid's (the coupling's u_f at i and j; lubrication.H, flowFactor)
    void addPair(int i, int j, double c, const double *n, double flow = 0.0);

    //- A lubricated wall contact of local atom i: resistance c, unit
    //  normal n from the wall to i, wall velocity vWall [run units]
    void addWall(int i, double c, const double *n, const double *vWall);

private:
    struct PairTerm { int i, j; double c; double n[3]; double flow; };
    struct WallTerm { int i; double c; double n[3]; double vWall[3]; };

    // the solve with step h [run units]; the force set makes the next
    // kick of h give the backward-Euler velocity
    void solve(double h, bool accumulateImpulse);
    void solveSystem(double h, bool accumulateImpulse);
    void findDragProperties();
    int nWithoutDrag() const;
    void findBrownianMotion();
    void findExplicitRatio();
    bool weakCandidate(const PairTerm & t, double h) const;
    void dampWeakPairs(double h, bool flow, bool thermal, std::uint64_t pairKey);
    std::uint64_t solveKey(std::uint64_t stream, double h) const;
    void thermalImpulse(std::uint64_t key, int tag, double K, double h, double *R) const;
    double pairThermalImpulse(std::uint64_t key, int a, int b, double c, double h) const;
    void foldPeriodicImages();
    void findGroups();
    void solvePair(const PairTerm & t);
    void solveDense(const int *members, int n, const int *pairIdx, int nPairs);
    int conjugateGradients(const std::vector<int> & members, const std::vector<int> & pairs, bool global);
    void multiply(const std::vector<int> & members, const std::vector<int> & pairs,
                  const double *p, double *q) const;
    double dot(const std::vector<int> & members, const double *a, const double *b, bool global) const;

    std::vector<PairTerm> pairs_;
    std::vector<WallTerm> walls_;
    bool collecting_;

    // the coupling's per-atom drag properties (NULL without them); their
    // arrays move when atoms are added, so they are read at each solve
    Fix *Ksl_;
    Fix *uf_;
    Fix *dragforce_;
    Fix *impulse_;
    Fix *assigned_;

    // group bits of the time-integrated particles (the unknowns)
    int integrated_;

    // Brownian motion with the drag (property/global brownianTemperature
    // [K] and brownianSeed): k_B T [run units], 0 when off; the seed and
    // its two streams (the atoms' impulses, the pairs' noise); the random
    // impulses of this solve, 3 per atom
    static constexpr std::uint64_t atomStream = 0;
    static constexpr std::uint64_t pairStream = 0x5bd1e9955bd1e995ULL;
    double kT_;
    unsigned long seed_;
    std::vector<double> thermal_;
    std::vector<int> wallsOf_;      // wall contacts of each atom so far

    // weak pairs damped explicitly (see above): the largest c h/m at
    // either end (0: off), the candidates' sum S of c h/m at each atom
    // (ghosts too), the explicit pairs' impulses over the step [run
    // units], 3 per local atom, and whether this solve has any
    static constexpr double explicitBudget = 0.5;
    double explicitRatio_;
    std::vector<double> weakSum_, explicitImpulse_;
    bool anyExplicit_;

    // what pack_comm sends: p_ (3 per atom) and/or weakSum_ (1)
    bool commVectors_, commWeakSum_;

    // step of the current solve [run units]
    double h_;

    // work arrays, 3 per atom (p includes ghosts); the matrix's diagonal
    // blocks and their inverses, 6 per atom
    std::vector<double> x_, r_, z_, p_, q_, r0_, blockA_, blockInv_;

    // groups of coupled particles: root of each atom, members and pairs
    // (indices into pairs_) sorted by root with their starts, the groups
    // with a ghost partner, and those of the global solve
    std::vector<int> parent_, groupStart_, pairStart_, groupMembers_, groupPairs_, fill_;
    std::vector<char> groupBoundary_;
    std::vector<int> boundaryMembers_, boundaryPairs_;

    // the particles with a pair or wall term (the others are updated
    // alone, without blocks), as a flag per atom and a list
    std::vector<char> isCoupled_;
    std::vector<int> coupled_;
    std::vector<int> groupScratch_, pairScratch_;

    // dense solve of a small group: matrix, right-hand side, and each
    // member's place in it
    std::vector<double> dense_, rhs_;
    std::vector<int> slot_;

    // statistics of the run
    long nSolves_;
    long nIterations_;
    int maxIterations_;
    long nNotConverged_;
    double seconds_;                // wall-clock time of the updates [s]
    double nGlobalMembers_;         // this rank's members of the global solves
    double nPairsSeen_, nPairsExplicit_;    // this rank's lubricated pairs, the explicit ones
};

}

#endif
