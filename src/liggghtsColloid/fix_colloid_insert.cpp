/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: see fix_colloid_insert.h.
------------------------------------------------------------------------- */

#include "fix_colloid_insert.h"
#include "colloid_append_fix.h"
#include <mpi.h>
#include "atom.h"
#include "atom_vec.h"
#include "domain.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const char fixId[] = "colloid_insert";
const char fixStyle[] = "colloid/insert";

}

FixColloidInsert::FixColloidInsert(LAMMPS *lmp, int narg, char **arg)
: Fix(lmp, narg, arg),
  radius_(0.0),
  density_(0.0),
  type_(1),
  created_(0)
{
    force_reneighbor = 1;
    next_reneighbor = -1;
}

int FixColloidInsert::setmask()
{
    return PRE_EXCHANGE;
}

FixColloidInsert *FixColloidInsert::attach(LAMMPS *lmp)
{
    return Colloid::colloidAttachFix<FixColloidInsert>(lmp, fixId, fixStyle);
}

bool FixColloidInsert::queue(int n, const double *x, const double *v, double radius,
                             double density, int type)
{
    if (type < 1 || type > atom->ntypes) return false;
    x_.assign(x, x + 3*n);
    v_.assign(v, v + 3*n);
    radius_ = radius;
    density_ = density;
    type_ = type;
    created_ = -1;
    next_reneighbor = update->ntimestep + 1;
    return true;
}

void FixColloidInsert::pre_exchange()
{
    if (created_ >= 0 || update->ntimestep != next_reneighbor) return;

    // The ids follow the largest present now
    int maxTag = 0;
    for (int i = 0; i < atom->nlocal; i++)
        if (atom->tag[i] > maxTag) maxTag = atom->tag[i];
    int firstTag = 0;
    MPI_Allreduce(&maxTag, &firstTag, 1, MPI_INT, MPI_MAX, world);
    firstTag++;

    for (int j = 0; j < modify->nfix; j++)
        if (modify->fix[j]->create_attribute) modify->fix[j]->pre_set_arrays();

    const int n = static_cast<int>(x_.size()/3);
    const double mass = 4.0/3.0*3.14159265358979323846*radius_*radius_*radius_*density_;
    long long created = 0;
    for (int k = 0; k < n; k++)
    {
        double p[3] = {x_[3*k], x_[3*k + 1], x_[3*k + 2]};
        domain->remap(p);
        bool mine = true;
        for (int d = 0; d < 3; d++)
            mine = mine && p[d] >= domain->sublo[d] && p[d] < domain->subhi[d];
        if (!mine) continue;

        atom->avec->create_atom(type_, p);
        const int m = atom->nlocal - 1;
        atom->tag[m] = firstTag + k;
        atom->mask[m] = 1;      // group all
        for (int d = 0; d < 3; d++)
        {
            atom->v[m][d] = v_[3*k + d];
            atom->omega[m][d] = 0.0;
        }
        atom->radius[m] = radius_;
        atom->density[m] = density_;
        atom->rmass[m] = mass;
        if (atom->contact_radius_flag) atom->contact_radius[m] = radius_;
        for (int j = 0; j < modify->nfix; j++)
            if (modify->fix[j]->create_attribute) modify->fix[j]->set_arrays(m);
        created++;
    }

    MPI_Allreduce(&created, &created_, 1, MPI_LONG_LONG, MPI_SUM, world);
    bigint nlocal = atom->nlocal;
    MPI_Allreduce(&nlocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (atom->map_style)
    {
        atom->nghost = 0;
        atom->map_init();
        atom->map_set();
    }
    x_.clear();
    v_.clear();
    next_reneighbor = -1;
}
