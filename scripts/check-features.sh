#!/usr/bin/env bash
# The crate without its default feature `gui`: the library, the command line and the Python
# extension's build (`--no-default-features`, `--features python`) name no crate of the GUI stack (eframe, egui,
# wgpu, winit, the X11/Wayland and Vulkan crates) and are clippy-clean. Fails naming the crates.
set -euo pipefail
cd "$(dirname "$0")/.."

# Every crate of the GUI stack, by name (epaint_default_fonts is font data the figures embed,
# with no dependency of its own, so it is allowed).
gui='^(eframe|egui.*|epaint|emath|ecolor|wgpu.*|naga|winit|glow|glutin.*|ash|gpu-.*|khronos.*|raw-window-handle|x11.*|xkb.*|wayland.*|smithay.*|sctk.*|calloop.*|arboard|accesskit.*|kittest)$'
for features in "" "python"; do
    found=$(cargo tree --no-default-features ${features:+--features "$features"} -e normal \
        --prefix none --format '{p}' | sed 's/ .*//' | sort -u | grep -E "$gui" || true)
    if [ -n "$found" ]; then
        echo "check-features: --no-default-features ${features:+--features $features }pulls in GUI crates:" $found >&2
        exit 1
    fi
done

# One clippy run covers the library, the binary and the Python module without `gui` (the
# library without `python` differs only by the module's `cfg`).
cargo clippy --no-default-features --features python --lib --bins -- -D warnings

