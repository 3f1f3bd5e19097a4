#!/usr/bin/env bash
# The Python package's tests (run by scripts/test.sh after `cargo test`): builds the wheel with
# maturin into a fresh virtual environment under target/ and runs tests/python with pytest,
# comparing against the samplescope binary `cargo test` built (target/debug/samplescope).
# The wheel is built with cargo's dev profile in the same target directory as the tests, so
# the dependencies the two builds share (same features) compile once. Fails, never skips.
set -euo pipefail
cd "$(dirname "$0")/.."

VENV=target/python-venv
rm -rf "$VENV" target/python-wheels
python3 -m venv "$VENV"
"$VENV/bin/python" -m pip install -q --disable-pip-version-check "maturin>=1.9,<2" pytest numpy scipy

"$VENV/bin/maturin" build --profile dev --interpreter "$VENV/bin/python" --out target/python-wheels
"$VENV/bin/python" -m pip install -q --disable-pip-version-check target/python-wheels/samplescope-*.whl

if [ ! -x target/debug/samplescope ]; then
    cargo build --bin samplescope
fi
# From outside the checkout, so that `import samplescope` is the installed wheel.
SAMPLESCOPE_BIN="$PWD/target/debug/samplescope" "$VENV/bin/python" -m pytest -q -p no:cacheprovider \
    --rootdir "$PWD/tests/python" "$PWD/tests/python"
