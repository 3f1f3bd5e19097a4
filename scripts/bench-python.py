#!/usr/bin/env python3
"""The Python module against scipy.stats.qmc, in one run: points("sobol", 2**20, dims=8)
against Sobol(8, scramble=False).random(2**20), and discrepancy(x, "CD") against
scipy.stats.qmc.discrepancy(x, method="CD") (N points in 8 dimensions, N chosen so that scipy
takes seconds). Each timing is the best of REPEATS runs; prints the times and the ratios
(scipy's time / ours: > 1 means samplescope is faster), and checks that the numbers agree.

    python scripts/bench-python.py [N_DISCREPANCY]
"""

import sys
import time

import numpy as np
from scipy.stats import qmc

import samplescope

REPEATS = 3


def best(f):
    times, result = [], None
    for _ in range(REPEATS):
        t = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - t)
    return min(times), result


def main(n_disc=8192):
    n_disc = int(n_disc)
    n = 2**20
    ours_t, ours = best(lambda: samplescope.points("sobol", n, dims=8))
    theirs_t, theirs = best(lambda: qmc.Sobol(8, scramble=False).random(n))
    same = np.array_equal(ours, theirs)
    print(f"points('sobol', 2**20, dims=8)   {ours_t * 1e3:9.1f} ms")
    print(f"scipy Sobol(8).random(2**20)     {theirs_t * 1e3:9.1f} ms")
    print(f"  ratio scipy/samplescope        {theirs_t / ours_t:9.2f}   (bit-identical: {same})")

    x = qmc.Sobol(8, scramble=True, seed=1).random(n_disc)
    ours_t, ours = best(lambda: samplescope.discrepancy(x, "CD"))
    theirs_t, theirs = best(lambda: qmc.discrepancy(x, method="CD"))
    print(f"discrepancy(x, 'CD'), N = {n_disc}, d = 8  {ours_t * 1e3:9.1f} ms")
    print(f"scipy discrepancy(x, method='CD')      {theirs_t * 1e3:9.1f} ms")
    print(
        f"  ratio scipy/samplescope              {theirs_t / ours_t:9.2f}   "
        f"(relative difference {abs(ours - theirs) / theirs:.1e})"
    )


if __name__ == "__main__":
    main(*sys.argv[1:])
