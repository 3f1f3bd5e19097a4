"""samplescope.points and samplescope.patterns: the CLI's numbers bit for bit, SciPy's Sobol'
and Halton points, bad input as ValueError with the CLI's message, the catalogue."""
import subprocess

import numpy as np
import pytest
from scipy.stats import qmc

import samplescope


def cli_points(cli, pattern, n, dims=None, seed=None, **params):
    args = ["points", pattern, "-n", n]
    if dims is not None:
        args += ["--dims", dims]
    if seed is not None:
        args += ["--seed", seed]
    for key, value in params.items():
        if isinstance(value, bool):
            value = str(value).lower()
        elif isinstance(value, (list, tuple)):
            value = "[" + ",".join(repr(float(v)) for v in value) + "]"
        args += ["--set", f"{key}={value}"]
    lines = cli(*args).splitlines()
    rows = [[float(v) for v in line.split(",")] for line in lines[1:]]
    return lines[0], np.array(rows, dtype=np.float64).reshape(len(rows), -1)


def same_bits(a, b):
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


CASES = [
    ("random", 100, None, None, {}),
    ("random", 64, 5, 7, {}),
    ("jitter", 64, None, 3, {"amount": 0.5}),
    ("nrooks", 50, None, 11, {}),
    ("lhs", 40, 6, 2, {}),
    ("multijitter", 36, None, 1, {}),
    ("cmj", 36, None, 4, {"cols": 4}),
    ("poisson-dart", 60, None, 5, {"radius": 0.05}),
    ("poisson-bridson", 80, None, 9, {}),
    ("best-candidate", 70, None, 2, {"m": 3}),
    ("halton", 128, None, None, {}),
    ("halton", 128, 8, None, {"scramble": "owen"}),
    ("hammersley", 90, 4, None, {}),
    ("halton-zaremba", 33, None, None, {"base_x": 3, "base_y": 5}),
    ("sobol", 256, None, None, {}),
    ("sobol", 256, 12, 6, {"scramble": "owen"}),
    ("sobol", 100, 3, 8, {"scramble": "random-digit", "skip": 5}),
    ("pmj02", 128, None, 12, {}),
    ("fibonacci", 89, None, None, {}),
    ("rank1", 101, 5, None, {}),
    ("kronecker", 64, 3, None, {}),
    ("kronecker", 64, None, None, {"offset_x": 0.25, "offset_y": 0.125}),
    ("padded", 64, 6, 13, {"base": "sobol"}),
    ("grid", 64, 3, None, {}),
    ("lloyd", 50, None, 3, {"iterations": 4}),
]


@pytest.mark.parametrize("pattern,n,dims,seed,params", CASES)
def test_points_equal_the_cli_bit_for_bit(cli, pattern, n, dims, seed, params):
    header, expected = cli_points(cli, pattern, n, dims, seed, **params)
    kwargs = {} if dims is None else {"dims": dims}
    if seed is not None:
        kwargs["seed"] = seed
    got = samplescope.points(pattern, n, **kwargs, **params)
    d = 2 if dims is None else dims
    assert header == ("x,y" if d == 2 else ",".join(f"x{k}" for k in range(d)))
    assert got.dtype == np.float64 and got.shape == (n, d)
    assert got.flags["C_CONTIGUOUS"]
    assert same_bits(got, expected), f"{pattern}: first difference at {np.argwhere(got != expected)[:1]}"


def test_default_seed_is_the_clis():
    # `samplescope points random -n 32` uses seed 0; so does points() without a seed.
    assert same_bits(samplescope.points("random", 32), samplescope.points("random", 32, seed=0))
    assert not np.array_equal(samplescope.points("random", 32), samplescope.points("random", 32, seed=1))


@pytest.mark.parametrize("dims", [1, 2, 3, 8, 32])
def test_sobol_is_scipys_bit_for_bit(dims):
    ours = samplescope.points("sobol", 512, dims=dims)
    theirs = qmc.Sobol(dims, scramble=False).random(512)
    assert same_bits(ours, theirs)


@pytest.mark.parametrize("dims", [1, 2, 3, 8, 32])
def test_halton_is_scipys_within_two_ulp(dims):
    # SciPy sums the radical inverse's digits in floating point (off by ≤ 2 ulp); ours is
    # correctly rounded (README, "Dimensions").
    ours = samplescope.points("halton", 512, dims=dims)
    theirs = qmc.Halton(dims, scramble=False).random(512)
    assert ours.shape == theirs.shape
    ulps = np.abs(ours.view(np.int64) - theirs.view(np.int64))
    assert ulps.max() <= 2
    assert (ulps == 0).mean() > 0.5


@pytest.mark.parametrize(
    "call,cli_args",
    [
        (lambda: samplescope.points("no-such", 10), ["points", "no-such", "-n", "10"]),
        (lambda: samplescope.points("jitter", 16, foo=1), ["points", "jitter", "-n", "16", "--set", "foo=1"]),
        (lambda: samplescope.points("jitter", 16, amount=2.5), ["points", "jitter", "-n", "16", "--set", "amount=2.5"]),
        (lambda: samplescope.points("jitter", 16, amount=True), ["points", "jitter", "-n", "16", "--set", "amount=true"]),
        (lambda: samplescope.points("halton", 16, scramble="nope"), ["points", "halton", "-n", "16", "--set", "scramble=nope"]),
        (lambda: samplescope.points("fibonacci", 10), ["points", "fibonacci", "-n", "10"]),
        (lambda: samplescope.points("jitter", 16, dims=3), ["points", "jitter", "-n", "16", "--dims", "3"]),
        (lambda: samplescope.points("sobol", 16, dims=0), ["points", "sobol", "-n", "16", "--dims", "0"]),
        (lambda: samplescope.points("sobol", 16, dims=2000), ["points", "sobol", "-n", "16", "--dims", "2000"]),
        (lambda: samplescope.points("poisson-dart", 100, radius=0.5), ["points", "poisson-dart", "-n", "100", "--set", "radius=0.5"]),
        (lambda: samplescope.points("random", 0), ["points", "random", "-n", "0"]),
        (lambda: samplescope.points("random", 10**9), ["points", "random", "-n", str(10**9)]),
    ],
)
def test_bad_input_is_a_value_error_with_the_clis_message(cli, call, cli_args):
    done = subprocess.run([cli.path, *cli_args], capture_output=True, text=True)
    assert done.returncode == 2
    message = done.stderr.strip().splitlines()[0]
    with pytest.raises(ValueError) as e:
        call()
    if cli_args[3] in ("0", str(10**9)):
        # The argument parser frames -n's message: "invalid value '0' for '-n <N>': n = 0: …".
        assert message.endswith(": " + str(e.value))
    else:
        assert message == "error: " + str(e.value)


def test_a_seed_for_a_deterministic_pattern_is_refused_as_the_cli_refuses_it(cli):
    done = subprocess.run([cli.path, "points", "sobol", "-n", "8", "--seed", "3"], capture_output=True, text=True)
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        samplescope.points("sobol", 8, seed=3)
    # The same sentence, naming the Python argument instead of the flag.
    assert str(e.value) == done.stderr.strip()[len("error: "):].replace("--seed", "seed")


def test_negative_arguments_are_value_errors():
    for kwargs in ({"seed": -1}, {"dims": -3}):
        with pytest.raises(ValueError, match="must be"):
            samplescope.points("random", 8, **kwargs)
    with pytest.raises(ValueError, match=r"n = -4: must be an integer in 1\.\.="):
        samplescope.points("random", -4)


def test_allow_fewer_keeps_the_points_placed():
    with pytest.raises(ValueError, match="allow_fewer=True"):
        samplescope.points("poisson-dart", 400, seed=1, radius=0.05, max_misses=10)
    got = samplescope.points("poisson-dart", 400, seed=1, radius=0.05, max_misses=10, allow_fewer=True)
    assert got.shape[1] == 2 and 0 < got.shape[0] < 400
    with pytest.raises(ValueError, match="always places exactly N points"):
        samplescope.points("random", 10, allow_fewer=True)


def test_parameter_values_of_every_python_type():
    # A list, a NumPy array and a tuple give the same per-dimension or list value; an int where
    # a float is expected and a NumPy scalar are numbers.
    a = samplescope.points("jitter", 16, seed=2, amount=1)
    b = samplescope.points("jitter", 16, seed=2, amount=np.float32(1.0))
    assert same_bits(a, b)
    base = samplescope.points("kronecker", 16, offset_x=0.25)
    assert same_bits(base, samplescope.points("kronecker", 16, offset_x=np.float64(0.25)))


def test_patterns_is_the_catalogue_of_points_list(cli):
    catalogue = samplescope.patterns()
    listed = cli("points", "--list")
    names = [p["name"] for p in catalogue]
    assert len(names) == len(set(names)) >= 25
    for p in catalogue:
        assert f"{p['name']}\n    {p['summary']}\n" in listed
        assert isinstance(p["max_dims"], int) and p["max_dims"] >= 2
        assert isinstance(p["random"], bool)
        for s in p["params"]:
            assert {"name", "doc", "kind", "default", "allowed"} <= set(s)
            assert s["kind"] in {"int", "float", "scale", "choice", "bool", "list", "per_dim", "int_list"}
            assert f"--set {s['name']}=…  " in listed and s["doc"] in listed and s["allowed"] in listed
            if s["kind"] == "choice":
                assert s["default"] in s["options"]
            if s["kind"] in {"int", "float"}:
                assert s["min"] <= s["default"] <= s["max"]
            # Every default is accepted as a keyword argument.
    sobol = next(p for p in catalogue if p["name"] == "sobol")
    scramble = next(s for s in sobol["params"] if s["name"] == "scramble")
    assert scramble["default"] == "none" and "owen" in scramble["options"]
    assert next(p for p in catalogue if p["name"] == "jitter")["max_dims"] == 2


KEYWORDS = {"dims", "seed", "allow_fewer"}


def test_every_default_round_trips_as_keyword_arguments():
    for p in samplescope.patterns():
        # lhs's own `dims` (the hypercube its 2D projection is taken from) is shadowed by the
        # keyword `dims` (the number of columns returned).
        params = {s["name"]: s["default"] for s in p["params"] if s["name"] not in KEYWORDS}
        n = 89 if p["name"] == "fibonacci" else 64
        seed = {"seed": 5} if p["random"] else {}
        with_defaults = samplescope.points(p["name"], n, **seed, **params)
        assert same_bits(with_defaults, samplescope.points(p["name"], n, **seed))


def test_help_lists_the_patterns():
    doc = samplescope.points.__doc__
    for p in samplescope.patterns():
        assert f"    {p['name']} " in doc
