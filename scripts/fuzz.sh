#!/usr/bin/env bash
# Fuzzes the glTF loader and the scene file parser with libFuzzer (clang-14
# with ASan and UBSan, the `fuzz` preset) for SECONDS each (default 60),
# after the mutation replays every build runs; seeds from tests/fuzz/corpus
# and assets/scenes, keys from tests/fuzz/gltf.dict and scene.dict.
#   scripts/fuzz.sh [SECONDS]     (CMAKE_BUILD_PARALLEL_LEVEL: build jobs, default 2)
# Installs clang-14 and its runtime libraries if missing; the project's
# other packages come from scripts/setup.sh. Exit 0: no crash. libFuzzer's
# whole output goes to build/fuzz/fuzz.log; its final figures (executions,
# coverage, features, corpus) are printed before ctest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
for package in clang-14 libclang-rt-14-dev; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    as_root=(); [[ $(id -u) -eq 0 ]] || as_root=(sudo)
    "${as_root[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends "$package"
  fi
done
seconds=${1:-60}
[[ $seconds =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS]" >&2; exit 2; }
cmake --preset fuzz -D SHADELAB_FUZZ_SECONDS="$seconds" >/dev/null
cmake --build --preset fuzz -j "${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
log=build/fuzz/fuzz.log
status=0
ctest --preset fuzz --verbose >"$log" 2>&1 || status=$?
grep -E '#[0-9]+[[:space:]]+DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb|Test +#[0-9]+:' "$log" || true
summary=$(grep -E '^[0-9]+% tests passed' "$log" | tail -n 1) || true
echo "${summary:-$(tail -n 1 "$log")}"
exit "$status"
