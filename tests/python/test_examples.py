"""The scripts in examples/ run without a display and print what they say."""
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_three_samplers_runs(tmp_path):
    out = tmp_path / "three.png"
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("DISPLAY", None)
    done = subprocess.run(
        [sys.executable, str(ROOT / "examples" / "three_samplers.py"), str(out)],
        capture_output=True, text=True, env=env, cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert [l.split()[0] for l in lines[:3]] == ["random", "jitter", "sobol"]
    # Jittered and scrambled Sobol' points keep farther apart than white noise.
    d = {l.split()[0]: float(l.split()[-1]) for l in lines[:3]}
    assert d["random"] < d["jitter"] and d["random"] < d["sobol"]
    try:
        import matplotlib  # noqa: F401
        assert out.stat().st_size > 0
    except ImportError:
        assert lines[3] == "matplotlib is not installed: no figure"
