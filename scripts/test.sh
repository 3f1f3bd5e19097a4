#!/usr/bin/env bash
# The test command of the README: every unit, integration, CLI and UI test.
# The UI snapshot tests need a wgpu adapter (Mesa lavapipe or llvmpipe); with
# SAMPLESCOPE_REQUIRE_GPU_ADAPTER=1 (set here) a missing adapter fails the run instead of skipping.
set -euo pipefail
cd "$(dirname "$0")/.."
export SAMPLESCOPE_REQUIRE_GPU_ADAPTER=1
cargo test "$@"
