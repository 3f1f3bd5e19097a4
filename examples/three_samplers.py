"""Three samplers side by side: white noise, jittered and Owen-scrambled Sobol' points, their
discrepancies and minimum distance, and (with matplotlib installed) a figure of the three
point sets over their periodograms (averaged over 16 realizations) and radial power spectra.

    python examples/three_samplers.py [OUT.png]

Runs without a display (matplotlib's Agg backend); tests/python/test_examples.py runs it.
"""
import sys

import numpy as np

import samplescope

N, SIZE, REALIZATIONS = 1024, 128, 16
SAMPLERS = [("random", {}), ("jitter", {}), ("sobol", {"scramble": "owen"})]


def main(out=None):
    sets, spectra = {}, {}
    for name, params in SAMPLERS:
        p = samplescope.points(name, N, seed=1, **params)
        sets[name] = p
        spectra[name] = samplescope.periodogram(
            name, n=N, size=SIZE, realizations=REALIZATIONS, seed=1, **params
        )
        stats = samplescope.analyze(p, size=32)
        print(
            f"{name:8s} {p.shape}  L2-star {samplescope.discrepancy(p):.3e}  "
            f"CD² {samplescope.discrepancy(p, 'CD'):.3e}  min distance {stats['min_distance']:.5f}"
        )
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no figure")
        return sets
    fig, axes = plt.subplots(3, len(sets), figsize=(4 * len(sets), 12))
    half = SIZE // 2
    for col, (name, p) in enumerate(sets.items()):
        power, raps = spectra[name]
        axes[0, col].scatter(p[:, 0], p[:, 1], s=1)
        axes[0, col].set(title=name, xlim=(0, 1), ylim=(0, 1), aspect="equal")
        shown = power.copy()
        shown[half, half] = np.nan  # DC (= N) off the colour scale
        axes[1, col].imshow(
            np.log10(np.maximum(shown, 1e-10)), origin="lower", cmap="viridis",
            extent=(-half, half, -half, half), vmin=-2, vmax=1,
        )
        axes[1, col].set(title=f"log10 P, {REALIZATIONS} realizations", xlabel="kx", ylabel="ky")
        axes[2, col].plot(raps[:, 0], raps[:, 1])
        axes[2, col].set(title="radially averaged power", xlabel="|k|", ylim=(0, 3))
    fig.tight_layout()
    fig.savefig(out or "three_samplers.png", dpi=80)
    print(f"wrote {out or 'three_samplers.png'}")
    return sets


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else None)
