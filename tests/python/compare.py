"""What the tests that compare the module with the command line share (the `cli` fixture of
conftest.py runs it): its JSON output, the comparison of an object with the CLI's, and the
checkout's root."""

import json
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cli_json(cli, *args):
    """The JSON object `samplescope ARGS…` prints."""
    return json.loads(cli(*args))


def same_except_timings(ours, theirs):
    """Every key of the CLI's JSON object `theirs` is in `ours` with the same value, the
    timings (which differ from run to run) aside."""
    for key, value in theirs.items():
        if key != "timings_ms":
            assert ours[key] == value, key
