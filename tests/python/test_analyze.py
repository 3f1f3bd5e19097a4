"""analyze() and periodogram() against `samplescope analyze --points FILE --json` (the same
keys and numbers; the arrays against --spectrum-data, --raps and --rdf)."""

import csv

import numpy as np
import pytest

import samplescope
from compare import cli_json

TIMINGS = "timings_ms"


def same_json(ours, theirs):
    """Every key and value of the CLI's object (timings aside) in ours, and no other key but
    the arrays."""
    arrays = {"periodogram", "raps", "anisotropy", "rdf"}
    assert set(ours) - arrays == set(theirs)
    for key, value in theirs.items():
        if key != TIMINGS:
            assert ours[key] == value, key


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return np.array([[float(v) for v in r] for r in rows[1:]])


def test_2d_points_match_the_cli(cli, tmp_path):
    x = np.random.default_rng(3).random((256, 2))
    np.save(tmp_path / "p.npy", x)
    theirs = cli_json(cli, 
        "analyze", "--points", tmp_path / "p.npy", "--json", "--size", 64,
        "--spectrum-data", tmp_path / "s.csv", "--raps", tmp_path / "r.csv",
        "--rdf", tmp_path / "g.csv",
    )
    ours = samplescope.analyze(x, size=64)
    same_json(ours, theirs)
    assert ours["periodogram"].shape == (64, 64)
    spectrum = read_csv(tmp_path / "s.csv")
    # CSV rows: ky outer, kx inner, from -M/2: the array's row-major order.
    assert np.array_equal(ours["periodogram"].ravel(), spectrum[:, 2])
    assert np.array_equal(spectrum[:, 0].reshape(64, 64)[0], np.arange(-32, 32))
    assert ours["periodogram"][32, 32] == pytest.approx(256)
    assert np.array_equal(ours["raps"], read_csv(tmp_path / "r.csv"))
    assert np.array_equal(ours["rdf"], read_csv(tmp_path / "g.csv"))
    assert ours["anisotropy"].shape[1] == 2


def test_exact_dft_and_tolerance_are_the_cli_flags(cli, tmp_path):
    x = np.random.default_rng(4).random((64, 2))
    np.save(tmp_path / "p.npy", x)
    theirs = cli_json(cli, "analyze", "--points", tmp_path / "p.npy", "--json", "--size", 32, "--exact")
    same_json(samplescope.analyze(x, size=32, exact=True), theirs)
    theirs = cli_json(cli, 
        "analyze", "--points", tmp_path / "p.npy", "--json", "--size", 32, "--tolerance", "1e-3"
    )
    same_json(samplescope.analyze(x, size=32, tolerance=1e-3), theirs)
    with pytest.raises(ValueError, match="tolerance: not with exact=True"):
        samplescope.analyze(x, exact=True, tolerance=1e-3)
    with pytest.raises(ValueError, match=r"tolerance = 0.5: must be a number in \[1e-12, 1e-2\]"):
        samplescope.analyze(x, tolerance=0.5)


def test_d_dimensional_points_match_the_cli(cli, tmp_path):
    x = np.random.default_rng(6).random((128, 5))
    np.save(tmp_path / "p.npy", x)
    theirs = cli_json(cli, "analyze", "--points", tmp_path / "p.npy", "--json")
    ours = samplescope.analyze(x)
    theirs.pop("file")
    assert ours.pop("file") == "points"
    assert ours == theirs
    from scipy.stats import qmc

    assert ours["centered_discrepancy"] == pytest.approx(qmc.discrepancy(x, method="CD"), rel=1e-9)


def test_projection_matches_the_cli(cli, tmp_path):
    x = np.random.default_rng(7).random((100, 4))
    np.save(tmp_path / "p.npy", x)
    theirs = cli_json(cli, 
        "analyze", "--points", tmp_path / "p.npy", "--project", "1,3", "--json", "--size", 32
    )
    same_json(samplescope.analyze(x, project=(1, 3), size=32), theirs)
    with pytest.raises(ValueError, match="--project 1,4: must be two different dimensions"):
        samplescope.analyze(x, project=(1, 4))


def test_periodogram_of_points_is_analyzes(tmp_path):
    x = np.random.default_rng(8).random((200, 2))
    p, raps = samplescope.periodogram(x, size=48)
    a = samplescope.analyze(x, size=48)
    assert np.array_equal(p, a["periodogram"])
    assert np.array_equal(raps, a["raps"])


def test_periodogram_of_a_pattern_averages_realizations(cli, tmp_path):
    theirs = tmp_path / "s.csv"
    cli_json(cli, 
        "analyze", "jitter", "-n", 256, "--realizations", 4, "--seed", 2, "--size", 32,
        "--json", "--spectrum-data", theirs,
    )
    p, raps = samplescope.periodogram("jitter", n=256, realizations=4, seed=2, size=32)
    assert np.array_equal(p.ravel(), read_csv(theirs)[:, 2])
    # White noise: E[P(k)] = 1 away from DC.
    q, _ = samplescope.periodogram("random", n=256, realizations=32, size=32)
    assert np.mean(np.delete(q.ravel(), 16 * 32 + 16)) == pytest.approx(1, abs=0.05)


def test_periodogram_of_k_realizations_is_their_mean():
    sets = np.random.default_rng(9).random((3, 100, 2))
    mean, _ = samplescope.periodogram(sets, size=16, exact=True)
    each = [samplescope.periodogram(s, size=16, exact=True)[0] for s in sets]
    assert mean == pytest.approx(sum(each) / 3, rel=1e-12)


def test_periodogram_refuses_what_the_cli_refuses():
    with pytest.raises(ValueError, match="n: required with a pattern"):
        samplescope.periodogram("sobol")
    with pytest.raises(ValueError, match="deterministic"):
        samplescope.periodogram("sobol", n=64, realizations=4)
    with pytest.raises(ValueError, match="seed: only with a pattern name"):
        samplescope.periodogram(np.full((4, 2), 0.5), seed=3)
    with pytest.raises(ValueError, match="unknown pattern|not a pattern|nope"):
        samplescope.periodogram("nope", n=16)
