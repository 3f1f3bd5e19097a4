"""converge() against `samplescope converge --json`."""

import numpy as np
import pytest

import samplescope
from compare import cli_json, same_except_timings as same


def test_2d_study_matches_the_cli(cli):
    theirs = cli_json(cli, 
        "converge", "--pattern", "jitter", "--integrand", "disk", "--integrand-set", "r=0.3",
        "--n", "16,64,256", "--realizations", 16, "--seed", 3, "--json",
    )
    ours = samplescope.converge(
        "jitter", "disk", n=[16, 64, 256], realizations=16, seed=3, integrand_params={"r": 0.3}
    )
    same(ours, theirs)
    assert ours["n"].tolist() == [16, 64, 256]
    assert ours["mse"].tolist() == [r["mse"] for r in theirs["rows"]]
    assert ours["bias2"].tolist() == [r["bias2"] for r in theirs["rows"]]
    # Jittered sampling of a disk: MSE ~ N^-1.5.
    assert -2.0 < ours["slope"] < -1.0


def test_d_dimensional_study_matches_the_cli(cli):
    theirs = cli_json(cli, 
        "converge", "--pattern", "sobol", "--integrand", "genz-gaussian", "--dims", 5,
        "--n", "64,256", "--realizations", 4, "--json",
    )
    ours = samplescope.converge("sobol", "genz-gaussian", n=[64, 256], realizations=4, dims=5)
    same(ours, theirs)
    assert ours["dims"] == 5


def test_one_realization_has_no_stderr():
    ours = samplescope.converge("random", "bilinear", n=[16, 32], realizations=1)
    assert np.isnan(ours["mse_stderr"]).all()


def test_refused_as_the_cli_refuses():
    with pytest.raises(ValueError, match="--no-shift"):
        samplescope.converge("random", "disk", n=[16], realizations=2, no_shift=True)
    with pytest.raises(ValueError, match="realizations"):
        samplescope.converge("jitter", "disk", n=[16], realizations=0)
    with pytest.raises(ValueError, match="nope"):
        samplescope.converge("jitter", "nope", n=[16], realizations=2)
