"""Error of a quantity over a ladder of one numerical setting: against a
closed form where one exists, else against the Richardson extrapolation of
the ladder; the observed order of convergence, and whether the ladder is in
its asymptotic range.

The ladder is given by its refinement measure h > 0 (a time step or cell
size itself; the reciprocal of a cut-off, whose exact answer is at infinite
range) and the quantity q on each rung.  Richardson's model of the error is
q(h) = q* + C h^p; three rungs h1 < h2 < h3 give the observed order p from
    (q3 - q2)/(q2 - q1) = (h3^p - h2^p)/(h2^p - h1^p)
and q* = q1 + (q1 - q2)/((h2/h1)^p - 1).  A fourth, coarser rung gives the
order again from rungs 2-4: the ladder counts as asymptotic when the two
orders agree within ASYMPTOTIC_SPREAD (relative) and both are positive; with
three rungs this cannot be checked and the result says so."""
import math

ASYMPTOTIC_SPREAD = 0.25   # relative difference of the two observed orders
FLAT = 1e-12               # changes below this (relative) count as none


def _order_from_three(h, q):
    """Observed order of h1 < h2 < h3 with q1, q2, q3, or None when the
    differences change sign (oscillation) or vanish"""
    d21, d32 = q[1] - q[0], q[2] - q[1]
    if d21 == 0 or d32 == 0 or (d21 > 0) != (d32 > 0):
        return None
    target = d32/d21

    def ratio(p):
        return (h[2]**p - h[1]**p)/(h[1]**p - h[0]**p)

    # ratio(p) increases with p for h1 < h2 < h3: bisection on [1e-3, 20]
    lo, hi = 1e-3, 20.0
    if not ratio(lo) <= target <= ratio(hi):
        return None
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if ratio(mid) < target:
            lo = mid
        else:
            hi = mid
    return 0.5*(lo + hi)


def _relative(value, base):
    return abs(value - base)/abs(base) if base != 0 else abs(value - base)


def analyse(h, q, reference=None):
    """h, q: the rungs (any order); reference: the closed form (one number,
    or one per rung) or None.

    Returns a dict:
      order      observed order (closed form: from the two finest rungs'
                 errors; else Richardson's from the three finest), or None
      richardson {order, extrapolated, asymptotic (True, False, None =
                 not checkable), coarseOrder} or None (fewer than 3 rungs
                 or no order)
      errors     relative error of each rung, in the order given (None
                 where unknown)
      estimated  Richardson's estimate of each rung's error, or None
      source     'closed form', 'Richardson', 'finest rung' (not
                 asymptotic: errors against the finest rung, a lower
                 bound) or 'no change'
    """
    if len(h) != len(q) or len(h) < 2:
        raise ValueError("a ladder needs at least two rungs with a value each")
    if any(x <= 0 for x in h) or len(set(h)) != len(h):
        raise ValueError("the refinement measures must be positive and distinct")
    rank = sorted(range(len(h)), key=lambda i: h[i])
    hs = [h[i] for i in rank]
    qs = [q[i] for i in rank]
    scale = max(abs(x) for x in qs) or 1.0

    result = {"order": None, "richardson": None, "errors": [None]*len(h),
              "estimated": [None]*len(h), "source": None}

    flat = all(abs(x - qs[0]) <= FLAT*scale for x in qs)
    if len(hs) >= 3 and not flat:
        p = _order_from_three(hs[:3], qs[:3])
        if p is not None:
            extrapolated = qs[0] + (qs[0] - qs[1])/((hs[1]/hs[0])**p - 1)
            coarse = _order_from_three(hs[1:4], qs[1:4]) if len(hs) >= 4 else None
            if len(hs) < 4:
                asymptotic = None
            else:
                asymptotic = coarse is not None and \
                    abs(p - coarse) <= ASYMPTOTIC_SPREAD*max(p, coarse)
            result["richardson"] = {"order": p, "extrapolated": extrapolated,
                                    "asymptotic": asymptotic, "coarseOrder": coarse}
            for i in range(len(h)):
                result["estimated"][i] = _relative(q[i], extrapolated)

    if reference is not None:
        refs = list(reference) if isinstance(reference, (list, tuple)) else [reference]*len(q)
        if len(refs) != len(q):
            raise ValueError("one closed form per rung, or one for all")
        result["source"] = "closed form"
        result["errors"] = [_relative(x, r) for x, r in zip(q, refs)]
        e0, e1 = result["errors"][rank[0]], result["errors"][rank[1]]
        if e0 > 0 and e1 > 0:
            result["order"] = math.log(e1/e0)/math.log(hs[1]/hs[0])
        return result

    if flat:
        result["source"] = "no change"
        result["errors"] = [_relative(x, qs[0]) for x in q]
        return result
    r = result["richardson"]
    if r is not None and r["asymptotic"] is not False:
        result["source"] = "Richardson"
        result["order"] = r["order"]
        result["errors"] = list(result["estimated"])
    else:
        result["source"] = "finest rung"
        finest = rank[0]
        result["errors"] = [None if i == finest else _relative(q[i], qs[0])
                            for i in range(len(h))]
    return result
