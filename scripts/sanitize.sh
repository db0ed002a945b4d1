#!/usr/bin/env bash
# Builds the `asan` preset (gcc, AddressSanitizer + UndefinedBehaviorSanitizer,
# validation layer on) and runs its test suite; prints how long each part
# took. Leaks inside lavapipe, LLVM and the validation layer are suppressed
# (tests/sanitizers/lsan.supp); any other report fails the test that hit it.
#   scripts/sanitize.sh [CTEST-ARGS...]   e.g. scripts/sanitize.sh -L cli
# CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$PWD/build/asan/mesa_shader_cache}
start=$(date +%s)
cmake --preset asan >/dev/null
cmake --build --preset asan -j "${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
built=$(date +%s)
status=0
ctest --preset asan "$@" || status=$?
done_at=$(date +%s)
echo "sanitize.sh: build $((built - start)) s, tests $((done_at - built)) s"
exit "$status"
