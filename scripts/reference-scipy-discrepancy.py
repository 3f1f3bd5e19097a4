#!/usr/bin/env python3
"""Reference values of the five L2 discrepancies for tests/it/cube_discrepancy.rs.

Writes tests/data/scipy/discrepancy/<name>.csv (the points, header x0,x1,..., every
coordinate with 17 significant digits, so it reads back to the same f64) and values.json:
for every set and measure, scipy.stats.qmc.discrepancy's value (scipy has no symmetric
discrepancy: null there), the same formula evaluated in 50-digit arithmetic (mpmath) on the
same f64 coordinates, and the sum of the absolute values of the formula's three terms (the
scale the final cancellation starts from).

Conventions (scipy's, which samplescope follows): `L2-star` is Warnock's T_N (the square root
is taken); `CD`, `WD` and `MD` are the squared discrepancies (no root); the symmetric
discrepancy SD is reported squared as well:
    SD^2 = (4/3)^d - (2/N) sum_i prod_k (1 + 2x_ik - 2x_ik^2)
           + (2^d/N^2) sum_i sum_j prod_k (1 - |x_ik - x_jk|).

Usage: python3 scripts/reference-scipy-discrepancy.py   (scipy >= 1.7, numpy, mpmath; a few
minutes). The sets are seeded: the output is the same on every run with the same scipy.
"""

import json
import os
import sys

import mpmath as mp
import numpy as np
import scipy
from scipy.stats import qmc

mp.mp.dps = 50
OUT = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "scipy", "discrepancy")

# (name, d, n, kind): seeded uniform random sets and scrambled Sobol' sets (low discrepancy:
# the terms cancel to a much smaller result).
SETS = [
    ("d1-random-n512", 1, 512, "random"),
    ("d2-random-n512", 2, 512, "random"),
    ("d2-sobol-n512", 2, 512, "sobol"),
    ("d3-random-n256", 3, 256, "random"),
    ("d3-sobol-n256", 3, 256, "sobol"),
    ("d8-random-n128", 8, 128, "random"),
    ("d8-sobol-n128", 8, 128, "sobol"),
    ("d32-random-n64", 32, 64, "random"),
    ("d32-sobol-n64", 32, 64, "sobol"),
]

H = mp.mpf(1) / 2
Q = mp.mpf(1) / 4


def formula(method, d):
    """(A, c1, g, c2, h) of A - (c1/N) sum prod g + (c2/N^2) sum sum prod h, exact."""
    if method == "L2-star":
        return (mp.mpf(3) ** -d, mp.mpf(2) ** (1 - d), lambda x: 1 - x * x, mp.mpf(1),
                lambda a, b: 1 - max(a, b))
    if method == "CD":
        return ((mp.mpf(13) / 12) ** d, mp.mpf(2),
                lambda x: 1 + H * abs(x - H) - H * abs(x - H) ** 2, mp.mpf(1),
                lambda a, b: 1 + H * abs(a - H) + H * abs(b - H) - H * abs(a - b))
    if method == "WD":
        return (-(mp.mpf(4) / 3) ** d, mp.mpf(0), None, mp.mpf(1),
                lambda a, b: mp.mpf(3) / 2 - abs(a - b) + abs(a - b) ** 2)
    if method == "MD":
        return ((mp.mpf(19) / 12) ** d, mp.mpf(2),
                lambda x: mp.mpf(5) / 3 - Q * abs(x - H) - Q * abs(x - H) ** 2, mp.mpf(1),
                lambda a, b: (mp.mpf(15) / 8 - Q * abs(a - H) - Q * abs(b - H)
                              - mp.mpf(3) / 4 * abs(a - b) + H * abs(a - b) ** 2))
    if method == "SD":
        return ((mp.mpf(4) / 3) ** d, mp.mpf(2), lambda x: 1 + 2 * x - 2 * x * x,
                mp.mpf(2) ** d, lambda a, b: 1 - abs(a - b))
    raise ValueError(method)


def high_precision(x, method):
    n, d = x.shape
    pts = [[mp.mpf(float(v)) for v in row] for row in x]
    a, c1, g, c2, h = formula(method, d)
    s1 = mp.mpf(0)
    if g is not None:
        for p in pts:
            prod = mp.mpf(1)
            for v in p:
                prod *= g(v)
            s1 += prod
    # h is symmetric: the diagonal once, the pairs i < j twice.
    s2 = mp.mpf(0)
    for i in range(n):
        p = pts[i]
        prod = mp.mpf(1)
        for v in p:
            prod *= h(v, v)
        s2 += prod
        for j in range(i + 1, n):
            q = pts[j]
            prod = mp.mpf(1)
            for k in range(d):
                prod *= h(p[k], q[k])
            s2 += 2 * prod
    t1 = c1 * s1 / n
    t2 = c2 * s2 / (n * n)
    value = a - t1 + t2
    if method == "L2-star":
        value = mp.sqrt(value)
    return value, abs(a) + abs(t1) + abs(t2)


def points(d, n, kind, seed):
    if kind == "random":
        return np.random.default_rng(seed).random((n, d))
    return qmc.Sobol(d, scramble=True, seed=seed).random(n)


def main():
    os.makedirs(OUT, exist_ok=True)
    records = []
    for seed, (name, d, n, kind) in enumerate(SETS, start=2026):
        x = points(d, n, kind, seed)
        with open(os.path.join(OUT, name + ".csv"), "w") as f:
            f.write(",".join(f"x{k}" for k in range(d)) + "\n")
            for row in x:
                f.write(",".join(repr(float(v)) for v in row) + "\n")
        back = np.loadtxt(os.path.join(OUT, name + ".csv"), delimiter=",", skiprows=1, ndmin=2)
        assert np.array_equal(back, x), name
        values = {}
        for method in ["L2-star", "CD", "WD", "MD", "SD"]:
            ref, scale = high_precision(x, method)
            sp = None if method == "SD" else float(qmc.discrepancy(x, method=method))
            values[method] = {
                "scipy": sp,
                "reference": mp.nstr(ref, 25, strip_zeros=False),
                "terms": float(scale),
            }
            print(name, method, sp, mp.nstr(ref, 20), file=sys.stderr)
        records.append({"name": name, "n": n, "dims": d, "kind": kind, "seed": seed,
                        "values": values})
    meta = {"generator": "scripts/reference-scipy-discrepancy.py",
            "scipy": scipy.__version__, "numpy": np.__version__, "mpmath": mp.__version__,
            "digits": mp.mp.dps, "sets": records}
    with open(os.path.join(OUT, "values.json"), "w") as f:
        json.dump(meta, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
