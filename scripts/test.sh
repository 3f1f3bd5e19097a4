#!/usr/bin/env bash
# The test command of the README: every unit, integration, CLI and UI test.
# The UI snapshot tests render with wgpu on Mesa (lavapipe or llvmpipe); without an adapter
# they fail, they never skip.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test "$@"
