"""Three samplers side by side: white noise, jittered and Owen-scrambled Sobol' points, their
minimum distance and (with matplotlib installed) a figure of the three point sets.

    python examples/three_samplers.py [OUT.png]

Runs without a display (matplotlib's Agg backend); tests/python/test_examples.py runs it.
"""
import sys

import numpy as np

import samplescope

N = 1024
SAMPLERS = [("random", {}), ("jitter", {}), ("sobol", {"scramble": "owen"})]


def min_distance(p):
    """The smallest toroidal distance between two points (O(N^2), fine for N = 1024)."""
    d = np.abs(p[:, None, :] - p[None, :, :])
    d = np.minimum(d, 1.0 - d)
    r2 = (d**2).sum(axis=-1)
    np.fill_diagonal(r2, np.inf)
    return float(np.sqrt(r2.min()))


def main(out=None):
    sets = {name: samplescope.points(name, N, seed=1, **params) for name, params in SAMPLERS}
    for name, p in sets.items():
        print(f"{name:8s} {p.shape}  min distance {min_distance(p):.5f}")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no figure")
        return sets
    fig, axes = plt.subplots(1, len(sets), figsize=(4 * len(sets), 4))
    for ax, (name, p) in zip(axes, sets.items()):
        ax.scatter(p[:, 0], p[:, 1], s=1)
        ax.set(title=name, xlim=(0, 1), ylim=(0, 1), aspect="equal")
    fig.savefig(out or "three_samplers.png", dpi=100)
    print(f"wrote {out or 'three_samplers.png'}")
    return sets


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else None)
