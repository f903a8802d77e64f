"""The close pairs of a particle cloud: every pair of spheres whose
surface gap |x_i - x_j| - r_i - r_j is below a bound, with the spanwise
(z) direction periodic as in the slot coater's DEM, found on a grid of
cells (no pair list of all N^2/2 pairs: the study's clouds hold 2e5
particles).  numpy only (a Debian package; scipy is not a dependency).

    close_pairs(position, radius, span, max_gap) -> (i, j, gap)

position [m] (N x 3), radius [m] (N), span [m] the z period (z taken
modulo span), max_gap [m]: indices i < j into the arrays and the gaps [m]
of the pairs with gap < max_gap (overlaps included: negative gaps),
sorted by gap, each pair once.  ValueError if the span is less than two
cells (2 x the largest radius + max_gap): a pair would meet itself
through two images."""
import numpy as np


def close_pairs(position, radius, span, max_gap):
    pos = np.array(position, dtype=float).reshape(-1, 3)
    r = np.array(radius, dtype=float).reshape(-1)
    n = len(r)
    if n < 2:
        return np.zeros(0, int), np.zeros(0, int), np.zeros(0)
    if max_gap <= 0:
        raise ValueError("max_gap %g m: must be positive" % max_gap)
    pos[:, 2] %= span
    # cells 2 x the largest radius + max_gap wide: every partner of a
    # sphere lies in the 27 cells around its own
    cell = 2*r.max() + max_gap
    if span < 2*cell:
        # a pair would meet itself through two images
        raise ValueError("span %g m is less than two cells of %g m (2 x largest radius "
                         "+ max_gap)" % (span, cell))
    # an image, one span up, of each sphere within a cell of z = 0: it
    # meets the spheres near z = span (the pairs across the periodic face)
    low = np.nonzero(pos[:, 2] < cell)[0]
    owner = np.concatenate([np.arange(n), low])
    p = np.concatenate([pos, pos[low] + [0, 0, span]])
    rr = r[owner]

    ijk = np.floor((p - p.min(axis=0))/cell).astype(np.int64)
    dims = ijk.max(axis=0) + 3          # a free layer beyond the last cell
    ijk += 1                             # and before the first
    key = (ijk[:, 0]*dims[1] + ijk[:, 1])*dims[2] + ijk[:, 2]
    order = np.argsort(key, kind="stable")
    sorted_key = key[order]

    found_i, found_j, found_gap = [], [], []
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dz in (-1, 0, 1):
                k = key + (dx*dims[1] + dy)*dims[2] + dz
                lo = np.searchsorted(sorted_key, k, side="left")
                hi = np.searchsorted(sorted_key, k, side="right")
                count = hi - lo
                a = np.repeat(np.arange(len(key)), count)
                # the members of each neighbour cell, run by run
                start = np.repeat(lo - np.cumsum(count) + count, count)
                b = order[start + np.arange(count.sum())]
                # each pair once (i < j), and only the close ones kept
                # from one neighbour cell to the next
                keep = owner[a] < owner[b]
                a, b = a[keep], b[keep]
                gap = np.linalg.norm(p[a] - p[b], axis=1) - rr[a] - rr[b]
                close = gap < max_gap
                found_i.append(owner[a[close]])
                found_j.append(owner[b[close]])
                found_gap.append(gap[close])
    i = np.concatenate(found_i)
    j = np.concatenate(found_j)
    gap = np.concatenate(found_gap)
    # a pair across the periodic face is found from both of its images
    pair = i*np.int64(n) + j
    pair, index = np.unique(pair, return_index=True)
    i, j, gap = i[index], j[index], gap[index]
    by_gap = np.argsort(gap, kind="stable")
    return i[by_gap], j[by_gap], gap[by_gap]
