#!/usr/bin/env bash
# Gouraud and Phong frame times of shadelab beside glmark2's shading scene
# (OpenGL on the same llvmpipe), interleaved in rounds because this machine's
# speed drifts by up to 2x within minutes: only figures from one round are
# comparable, so the ratio is taken per round and its median reported.
#   scripts/peer_bench.sh [ROUNDS] [SIZE] [SHADELAB_BINARY...]
# Needs glmark2 (Debian: glmark2-x11 glmark2-data) and an X display (Xvfb).
# shadelab draws two scenes: glmark2's own cat (/usr/share/glmark2/models/
# cat.3ds, 14,348 triangles, converted by scripts/glmark2_model.py and seen
# as glmark2 sets it up: 5 units away, 60 degree field of view, turned 54
# degrees, the middle of the 0-108 degrees glmark2's 3 s run turns it
# through) and assets/scenes/peer-shading.json (a 14,400-triangle Bezier
# teapot). shadelab's figure is the mean wall-clock interval between frame
# completions after the warm-up frames; glmark2's FPS is frames over elapsed
# time, a mean too (a median would hide our slow frames).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
size=${2:-800x600}
shift $(( $# < 2 ? $# : 2 ))
binaries=("$@")
[ ${#binaries[@]} -eq 0 ] && binaries=(build/release/shadelab)
command -v python3 >/dev/null || { echo "peer_bench: python3 not installed (apt install python3)" >&2; exit 2; }
command -v glmark2 >/dev/null || { echo "peer_bench: glmark2 not installed (apt install glmark2-x11 glmark2-data)" >&2; exit 2; }
[ -n "${DISPLAY:-}" ] || { echo "peer_bench: no DISPLAY (start Xvfb :99 & and export DISPLAY=:99)" >&2; exit 2; }
export VK_DRIVER_FILES="${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results="$work/results"
cat3ds=/usr/share/glmark2/models/cat.3ds
[ -f "$cat3ds" ] || { echo "peer_bench: $cat3ds missing (apt install glmark2-data)" >&2; exit 2; }
python3 scripts/glmark2_model.py "$cat3ds" "$work/cat.gltf" >&2
# glmark2's view: the model 5 units in front of the eye, a 60 degree field of
# view; one point light as glmark2's Phong has it (eye-space (0, 1, 0), 0.8),
# casting no shadow: glmark2's shading scene has none.
cat > "$work/cat.json" <<'JSON'
{
  "camera": {"eye": [0, 0, 5], "at": [0, 0, 0], "fovy": 60, "near": 1, "far": 1024},
  "ambient": 0.1,
  "background": 0,
  "lights": [{"type": "point", "position": [0, 1, 5], "intensity": 0.8, "shadows": false}],
  "objects": [{"name": "glmark2's cat", "gltf": "cat.gltf",
               "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 54}}]}]
}
JSON
scenes=("cat=$work/cat.json" "teapot=assets/scenes/peer-shading.json")
for round in $(seq "$rounds"); do
  for mode in gouraud phong; do
    fps=$(glmark2 --off-screen -s "$size" -b "shading:shading=$mode:duration=3" 2>&1 |
          sed -n 's/.*FPS: \([0-9]*\).*/\1/p')
    echo "$round $mode glmark2 $(awk -v f="$fps" 'BEGIN{printf "%.3f", 1000/f}')" >> "$results"
    for bin in "${binaries[@]}"; do
      for scene in "${scenes[@]}"; do
        mean=$("$bin" render "${scene#*=}" --size "$size" --frames 600 --mode "$mode" \
                 -o "$work/frame.png" 2>&1 | sed -n 's/.*wall median [0-9.]* ms, mean \([0-9.]*\) ms.*/\1/p')
        [ -n "$mean" ] || { echo "peer_bench: $bin failed on ${scene#*=}" >&2; exit 1; }
        echo "$round $mode ${scene%%=*}:$bin $mean" >> "$results"
      done
    done
  done
  echo "round $round of $rounds done" >&2
done
# Per mode and renderer: the median over rounds of each run's mean frame time, and the
# median of the per-round ratios to glmark2.
printf "%-8s %-40s %20s %17s\n" mode renderer "ms (median of rounds)" "ratio to glmark2"
awk '
  function median(list,   n, v, i, j, s) {
    n = split(list, v, " ")
    for (i = 2; i <= n; i++) { s = v[i]; for (j = i - 1; j > 0 && v[j] + 0 > s + 0; j--) v[j+1] = v[j]; v[j+1] = s }
    return n % 2 ? v[(n+1)/2] : (v[n/2] + v[n/2+1]) / 2 }
  $3 == "glmark2" { peer[$1" "$2] = $4; times[$2" glmark2"] = times[$2" glmark2"] " " $4; next }
  { times[$2" "$3] = times[$2" "$3] " " $4; ratios[$2" "$3] = ratios[$2" "$3] " " $4 / peer[$1" "$2] }
  END {
    for (k in times) { split(k, part, " ")
      printf "%-8s %-40s %20.3f %17s\n", part[1], part[2], median(times[k]),
             part[2] == "glmark2" ? "1" : sprintf("%.2f", median(ratios[k])) }
  }' "$results" | sort
