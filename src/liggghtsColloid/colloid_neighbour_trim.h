/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: dropping neighbours from one atom's row of
   a granular neighbour list, with their contact-history entries.

   A row of LIGGGHTS' granular pair list is the neighbours' indices
   (jlist), and, in the history list, one contact flag and dnum history
   values per neighbour in the same order. Dropping a neighbour must drop
   its flag and values with it, or the next neighbour inherits them (a
   contact would carry another contact's tangential spring).  Kept
   entries keep their order; the row is compacted in place.
------------------------------------------------------------------------- */

#ifndef COLLOID_NEIGHBOUR_TRIM_H
#define COLLOID_NEIGHBOUR_TRIM_H

namespace Colloid {

//- Keeps the neighbours j of the row (n entries) for which keep(j) is true
//  (j: the list entry, as LIGGGHTS stores it, flag bits included);
//  flags (one per neighbour) and history (dnum per neighbour) may be NULL.
//  Returns the number kept.
template<class Keep>
int trimNeighbourRow(int *jlist, int *flags, double *history, int dnum, int n, Keep keep)
{
    int kept = 0;
    for (int jj = 0; jj < n; jj++)
    {
        if (!keep(jlist[jj])) continue;
        if (kept != jj)
        {
            jlist[kept] = jlist[jj];
            if (flags) flags[kept] = flags[jj];
            if (history)
                for (int d = 0; d < dnum; d++) history[kept*dnum + d] = history[jj*dnum + d];
        }
        kept++;
    }
    return kept;
}

}

#endif
