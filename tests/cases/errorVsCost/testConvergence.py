#!/usr/bin/env python3
"""convergence.py (src/python) against ladders whose answer is known in
closed form, q(h) = q* + C h^p (+ a higher-order term):

  - exact power law, order 1.5, geometric ladder: Richardson's order and
    extrapolation recover p and q* to 1e-9 (relative), the ladder is
    asymptotic, each rung's estimated error equals |C| h^p/|q*|;
  - the same on a non-geometric ladder (h = 1, 0.7, 0.3, 0.2);
  - with a closed form: the observed order from the two finest rungs;
  - q* + h + 20 h^3, the cubic term dominant on the coarse rungs: the
    triplets' orders (1.83, 2.46) differ by more than 25 %: not asymptotic, the
    errors fall back to the finest rung (and the finest rung's is unknown);
  - oscillating differences: no Richardson order; flat ladder: no change.
Prints each check and PASS/FAIL."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "src", "python"))
import convergence  # noqa: E402

ok = True


def check(what, good):
    global ok
    print("%-70s %s" % (what, "ok" if good else "FAIL"))
    ok = ok and good


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol*max(abs(b), 1e-300)


qstar, C, p = 2.5, -0.8, 1.5
for h in ([0.4, 0.2, 0.1, 0.05], [1.0, 0.7, 0.3, 0.2]):
    q = [qstar + C*x**p for x in h]
    a = convergence.analyse(h, q)
    r = a["richardson"]
    check("power law h=%s: order %.12g" % (h, r["order"]), close(r["order"], p))
    check("power law: extrapolated %.15g" % r["extrapolated"], close(r["extrapolated"], qstar))
    check("power law: asymptotic", r["asymptotic"] is True and a["source"] == "Richardson")
    check("power law: estimated errors", all(
        close(e, abs(C)*x**p/qstar, 1e-6) for e, x in zip(a["errors"], h)))

h = [0.4, 0.2, 0.1, 0.05]
q = [qstar + C*x**2 for x in h]
a = convergence.analyse(h, q, reference=qstar)
check("closed form: observed order %.12g" % a["order"], close(a["order"], 2.0))
check("closed form: errors", a["source"] == "closed form" and all(
    close(e, abs(C)*x**2/qstar) for e, x in zip(a["errors"], h)))

q = [qstar + x + 20*x**3 for x in h]
a = convergence.analyse(h, q)
r = a["richardson"]
check("pre-asymptotic: orders %.3g (fine) %.3g (coarse)" % (r["order"], r["coarseOrder"]),
      r["asymptotic"] is False)
check("pre-asymptotic: errors against the finest rung", a["source"] == "finest rung"
      and a["errors"][3] is None and close(a["errors"][0], abs(q[0] - q[3])/abs(q[3])))

q = [1.0, 1.1, 1.05, 1.07]
a = convergence.analyse(h, q)
check("oscillating: no Richardson order", a["richardson"] is None and a["source"] == "finest rung")

a = convergence.analyse(h, [3.0]*4)
check("flat: no change", a["source"] == "no change" and max(a["errors"]) == 0)

try:
    convergence.analyse([0.1, 0.1], [1, 2])
    check("repeated rung refused", False)
except ValueError:
    check("repeated rung refused", True)

print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
