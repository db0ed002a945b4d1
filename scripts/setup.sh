#!/usr/bin/env bash
# Installs the Debian packages shadelab needs (only those missing), then
# configures and builds. Idempotent: a second run installs nothing and
# rebuilds only what changed.
#   scripts/setup.sh [debug|release]     (default: release)
set -euo pipefail
cd "$(dirname "$0")/.."

preset="${1:-release}"
packages=(
  build-essential cmake pkg-config python3
  mesa-vulkan-drivers libvulkan-dev vulkan-validationlayers
  glslang-tools glslang-dev
  libglfw3-dev libglm-dev libtinygltf-dev libopenimageio-dev openimageio-tools libpng-dev
  libimgui-dev libcli11-dev nlohmann-json3-dev libstb-dev libmeshoptimizer-dev
  libgtest-dev clang-format
  fonts-dejavu-core xvfb xauth
)

missing=()
for package in "${packages[@]}"; do
  # dpkg-query reports "install ok installed" only for fully installed packages.
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}"
  if [[ $(id -u) -eq 0 ]]; then
    as_root=()
  elif command -v sudo >/dev/null; then
    as_root=(sudo)
  else
    echo "setup: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
  "${as_root[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all ${#packages[@]} Debian packages present"
fi

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
