"""Shared fixtures of the Python tests: the samplescope command line the results are compared
with (SAMPLESCOPE_BIN, else target/debug/samplescope, which `cargo test` builds) and a runner
that returns its standard output."""
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _cli_path():
    path = os.environ.get("SAMPLESCOPE_BIN") or str(ROOT / "target" / "debug" / "samplescope")
    if not os.path.isfile(path):
        raise RuntimeError(
            f"{path}: the samplescope binary the tests compare with is missing; build it "
            "(`cargo build`) or set SAMPLESCOPE_BIN"
        )
    return path


@pytest.fixture(scope="session")
def cli():
    """Runs `samplescope ARGS…` and returns its standard output; a failure fails the test with
    its standard error."""
    path = _cli_path()

    def run(*args):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if done.returncode != 0:
            raise AssertionError(f"samplescope {' '.join(map(str, args))}: {done.stderr.strip()}")
        return done.stdout

    run.path = path
    return run
