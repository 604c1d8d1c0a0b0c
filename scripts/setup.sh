#!/usr/bin/env bash
# Set up a fresh Debian 12 machine for fieldlines: install the missing Debian packages (with
# apt-get when root; otherwise print the exact apt line and stop), then configure and build.
# Usage: scripts/setup.sh [cmake preset, default: release]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"

packages=(
  build-essential cmake ninja-build pkg-config git ccache mold
  libopencv-dev libopencv-contrib-dev libeigen3-dev nlohmann-json3-dev
  libimgui-dev libstb-dev libglfw3-dev libgl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  xvfb xauth xdotool x11-utils imagemagick
  clang libclang-rt-14-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -eq 0 ]]; then
    echo "setup: installing ${missing[*]}" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
  else
    echo "setup: missing Debian packages; run this, then re-run $0:" >&2
    echo "  sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
fi

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j"$(nproc)"
