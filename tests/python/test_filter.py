"""filter_response() against `samplescope filter KERNEL --json --response OUT.csv`."""

import csv

import numpy as np
import pytest

import samplescope
from compare import cli_json


@pytest.mark.parametrize(
    "kernel, params, cli_set, mode",
    [
        ("gaussian", {}, [], "separable"),
        ("lanczos", {"radius": 3}, ["radius=3"], "separable"),
        ("mitchell", {"b": 0.5, "c": 0.25}, ["b=0.5", "c=0.25"], "radial"),
    ],
)
def test_matches_the_cli(cli, tmp_path, kernel, params, cli_set, mode):
    out = tmp_path / "r.csv"
    args = ["filter", kernel, "--json", "--mode", mode, "--response", out]
    for s in cli_set:
        args += ["--set", s]
    theirs = cli_json(cli, *args)
    omega, magnitude, phase, metrics = samplescope.filter_response(kernel, mode=mode, **params)
    assert metrics == theirs
    with open(out) as f:
        rows = np.array([[float(v) for v in r] for r in list(csv.reader(f))[1:]])
    assert np.array_equal(omega, rows[:, 0])
    assert np.array_equal(magnitude, rows[:, 1])
    assert np.array_equal(phase, rows[:, 2])
    assert len(omega) == 513 and omega[-1] == 2.0


def test_parameters_are_checked_by_the_descriptors():
    with pytest.raises(ValueError, match="radius"):
        samplescope.filter_response("lanczos", radius=-1)
    with pytest.raises(ValueError, match="nonsense"):
        samplescope.filter_response("lanczos", nonsense=1)
    with pytest.raises(ValueError, match="mode"):
        samplescope.filter_response("gaussian", mode="diagonal")
    with pytest.raises(ValueError, match="bogus"):
        samplescope.filter_response("bogus")
