#!/usr/bin/env bash
# README command 2: set up, build with the validation layer on (debug
# preset), and run the whole test suite. The last line is ctest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh debug
export VK_DRIVER_FILES="${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
# A private shader cache keeps test runs independent of the user's cache.
export MESA_SHADER_CACHE_DIR="${MESA_SHADER_CACHE_DIR:-$PWD/build/debug/mesa_shader_cache}"
ctest --preset debug
