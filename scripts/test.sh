#!/usr/bin/env bash
# The test command of the README: installs the system packages the tests need (or names the
# command to install them), then runs every unit, integration, CLI and UI test, then the Python
# package's tests (the wheel built in a fresh virtual environment: scripts/python-tests.sh).
# The UI snapshot tests render with wgpu on Mesa (lavapipe or llvmpipe); without an adapter
# they fail, they never skip.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/system-packages.sh
cargo test "$@"
./scripts/python-tests.sh
