"""reconstruct() against `samplescope recon --json` (the report; the image against --out's
numbers through the same scene)."""

import numpy as np
import pytest

import samplescope
from compare import cli_json, same_except_timings as same


def test_scattered_matches_the_cli(cli):
    theirs = cli_json(cli, 
        "recon", "--signal", "zone-plate", "--signal-set", "k=40", "--pattern", "jitter",
        "-n", 4096, "--filter", "mitchell", "--size", 64, "--seed", 2, "--json",
    )
    image, reference, report = samplescope.reconstruct(
        signal="zone-plate", pattern="jitter", filter="mitchell", size=64, n=4096, seed=2,
        signal_params={"k": 40},
    )
    same(report, theirs)
    assert image.shape == reference.shape == (64, 64)
    assert np.sqrt(np.mean((image - reference) ** 2)) == pytest.approx(report["rmse"], rel=1e-12)


def test_supersampled_matches_the_cli(cli):
    theirs = cli_json(cli, "recon", "--spp", 4, "--size", 32, "--pattern", "sobol", "--json")
    _, _, report = samplescope.reconstruct(pattern="sobol", spp=4, size=32)
    same(report, theirs)


def test_given_points_are_the_samples():
    x = samplescope.periodogram  # noqa: F841 (module loaded)
    pts = np.random.default_rng(1).random((2048, 2))
    image, reference, report = samplescope.reconstruct(points=pts, size=32)
    assert report["rmse"] > 0
    # The same points again: the same image; other points: another.
    again, _, _ = samplescope.reconstruct(points=pts, size=32)
    assert np.array_equal(image, again)
    other, _, _ = samplescope.reconstruct(points=pts[::-1][:1024], size=32)
    assert not np.array_equal(image, other)
    with pytest.raises(ValueError, match="points: the samples are given"):
        samplescope.reconstruct(points=pts, pattern="sobol")


def test_refused_as_the_cli_refuses():
    with pytest.raises(ValueError, match="give n"):
        samplescope.reconstruct()
    with pytest.raises(ValueError, match="--size"):
        samplescope.reconstruct(n=64, size=0)
    with pytest.raises(ValueError, match="nope"):
        samplescope.reconstruct(n=64, signal="nope")
