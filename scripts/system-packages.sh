#!/usr/bin/env bash
# Installs the Debian packages samplescope's tests and window need (see README "System packages"),
# or, without root or sudo, names the exact command and fails. Does nothing when they are present.
#   mesa-vulkan-drivers, libvulkan1  - lavapipe software Vulkan: the wgpu adapter of the UI snapshot tests
#   libegl1, libgl1-mesa-dri         - llvmpipe through EGL/GL: the fallback wgpu adapter
#   libxkbcommon-x11-0               - keyboard handling for the eframe window (winit loads it at run time)
#   xvfb                             - a virtual X display, to run the real window on a headless machine
#   python3, python3-venv            - the Python package's tests: a virtual environment to build the wheel in
set -euo pipefail
PACKAGES=(mesa-vulkan-drivers libvulkan1 libegl1 libgl1-mesa-dri libxkbcommon-x11-0 xvfb python3 python3-venv)

if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "system-packages: not a Debian system; install the equivalents of: ${PACKAGES[*]}" >&2
    exit 0
fi
missing=()
for p in "${PACKAGES[@]}"; do
    if [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]; then
        missing+=("$p")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    SUDO="sudo"
else
    echo "system-packages: missing ${missing[*]}; install them with:" >&2
    echo "    sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
fi
echo "system-packages: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
