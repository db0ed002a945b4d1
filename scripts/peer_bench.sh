#!/usr/bin/env bash
# Gouraud and Phong frame times of shadelab beside glmark2's shading scene
# (OpenGL on the same llvmpipe), interleaved in rounds because this machine's
# speed drifts by up to 2x within minutes: only figures from one round are
# comparable, so the ratio is taken per round and its median reported.
#   scripts/peer_bench.sh [ROUNDS] [SIZE] [SHADELAB_BINARY...]
# Needs glmark2 (Debian: glmark2-x11 glmark2-data) and an X display (Xvfb).
# shadelab draws assets/scenes/peer-shading.json (a 14,400-triangle teapot
# against glmark2's 14,348-triangle cat); its figure is the wall-clock
# interval between frame completions (what glmark2's FPS measures too).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
size=${2:-800x600}
shift $(( $# < 2 ? $# : 2 ))
binaries=("$@")
[ ${#binaries[@]} -eq 0 ] && binaries=(build/release/shadelab)
command -v glmark2 >/dev/null || { echo "peer_bench: glmark2 not installed (apt install glmark2-x11 glmark2-data)" >&2; exit 2; }
[ -n "${DISPLAY:-}" ] || { echo "peer_bench: no DISPLAY (start Xvfb :99 & and export DISPLAY=:99)" >&2; exit 2; }
export VK_DRIVER_FILES="${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results="$work/results"
for round in $(seq "$rounds"); do
  for mode in gouraud phong; do
    fps=$(glmark2 --off-screen -s "$size" -b "shading:shading=$mode:duration=3" 2>&1 |
          sed -n 's/.*FPS: \([0-9]*\).*/\1/p')
    echo "$round $mode glmark2 $(awk -v f="$fps" 'BEGIN{printf "%.3f", 1000/f}')" >> "$results"
    for bin in "${binaries[@]}"; do
      wall=$("$bin" render assets/scenes/peer-shading.json --size "$size" --frames 600 \
               --mode "$mode" -o "$work/frame.png" 2>&1 | sed -n 's/.*wall median \([0-9.]*\) ms.*/\1/p')
      echo "$round $mode $bin $wall" >> "$results"
    done
  done
  echo "round $round of $rounds done" >&2
done
# Per mode and renderer: the median over rounds, and the median of the
# per-round ratios to glmark2.
printf "%-8s %-32s %10s %17s\n" mode renderer "median ms" "ratio to glmark2"
awk '
  function median(list,   n, v, i, j, s) {
    n = split(list, v, " ")
    for (i = 2; i <= n; i++) { s = v[i]; for (j = i - 1; j > 0 && v[j] + 0 > s + 0; j--) v[j+1] = v[j]; v[j+1] = s }
    return n % 2 ? v[(n+1)/2] : (v[n/2] + v[n/2+1]) / 2 }
  $3 == "glmark2" { peer[$1" "$2] = $4; times[$2" glmark2"] = times[$2" glmark2"] " " $4; next }
  { times[$2" "$3] = times[$2" "$3] " " $4; ratios[$2" "$3] = ratios[$2" "$3] " " $4 / peer[$1" "$2] }
  END {
    for (k in times) { split(k, part, " ")
      printf "%-8s %-32s %10.3f %17s\n", part[1], part[2], median(times[k]),
             part[2] == "glmark2" ? "1" : sprintf("%.2f", median(ratios[k])) }
  }' "$results" | sort
