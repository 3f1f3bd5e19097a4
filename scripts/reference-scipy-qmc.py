#!/usr/bin/env python3
"""Writes the SciPy reference point sets the d-dimensional Sobol' and Halton tests compare with
(tests/data/scipy/, read by tests/it/cube_patterns.rs).

    python3 scripts/reference-scipy-qmc.py [OUT_DIR]

Unscrambled scipy.stats.qmc.Sobol(d, scramble=False) and Halton(d, scramble=False): 256 points
in d = 1, 2, 3, 8, 32, and the first 64 points of d = 1024 restricted to dimensions 1000..1023
(the end of the table). Each file is CSV with the header x0,…,x{d−1} (or x1000,…,x1023) and
values written with Python's repr (the shortest text that reads back to the same double).
Made with SciPy 1.17.1; the files record the version in their first line (a `#` comment).
"""
import os
import sys

import numpy as np
import scipy
from scipy.stats import qmc

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "scipy")


def write(name, points, first_dim=0):
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, name), "w") as f:
        f.write(f"# scipy {scipy.__version__}: {name}\n")
        f.write(",".join(f"x{first_dim + d}" for d in range(points.shape[1])) + "\n")
        for row in points:
            f.write(",".join(repr(float(v)) for v in row) + "\n")


for d in (1, 2, 3, 8, 32):
    write(f"sobol-d{d}.csv", qmc.Sobol(d, scramble=False).random(256))
    write(f"halton-d{d}.csv", qmc.Halton(d, scramble=False).random(256))

write("sobol-d1024-dims1000-1023.csv",
      qmc.Sobol(1024, scramble=False).random(64)[:, 1000:], first_dim=1000)
write("halton-d1024-dims1000-1023.csv",
      qmc.Halton(1024, scramble=False).random(64)[:, 1000:], first_dim=1000)
