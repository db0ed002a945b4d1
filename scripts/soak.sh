#!/usr/bin/env bash
# Viewer soak (issue 20): runs `shadelab view` under its own Xvfb for about
# FRAMES frames (default 5000) of a script that presses every key, drags,
# scrolls, turns split screen on during a resize storm (1x1, 2x2, 3x100,
# 3000x2000, ...), minimises and restores, and samples VmRSS after each
# round. The first three rounds are the warm-up (every pipeline, filter and
# swapchain size made, and the heap grown to what a 3000x2000 split screen
# needs: 597, 655, then 703 MB, flat from there on in the 5,000-frame run);
# growth is measured from there to the end.
#   scripts/soak.sh [FRAMES [BINARY]]     (BINARY default build/release/shadelab)
# Environment: SOAK_VALIDATE=1 runs with the validation layer (about half
# the speed; any message fails), SOAK_MAX_GROWTH_KB (default 5120) the
# allowed growth, SOAK_KEEP=DIR keeps the script, output and screenshots.
# Exit 0: the viewer survived, printed no validation message and grew less
# than the limit. The last line is the summary.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-5000}
binary=$(realpath "${2:-build/release/shadelab}")
if ! [[ $frames =~ ^[0-9]+$ ]] || ((frames < 600)); then
  echo "usage: scripts/soak.sh [FRAMES (at least 600: 3 rounds of warm-up, 1 measured) [BINARY]]" >&2
  exit 2
fi
[[ -x $binary ]] || { echo "soak.sh: no binary '$binary' (build the release preset first)" >&2; exit 2; }
max_growth_kb=${SOAK_MAX_GROWTH_KB:-5120}
validate=--no-validate
[[ ${SOAK_VALIDATE:-0} == 1 ]] && validate=--validate
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
work=${SOAK_KEEP:-$(mktemp -d)}
mkdir -p "$work"
[[ -n ${SOAK_KEEP:-} ]] || trap 'rm -rf "$work"' EXIT
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$work/mesa_shader_cache}

# One round: 162 frames drawn. Every key of the viewer's table (Esc aside), the
# filter cycled through all five states with a frame drawn in each (anisotropic
# at a small size: it can be slow on llvmpipe), screenshots, then split screen
# through a resize storm, minimise / restore, and back to the start state.
round() {
  cat <<'EOF'
resize 640 360
key 1
frames 4
key 2
frames 4
key 3
frames 4
key 4
frames 4
key W
frames 4
key W
key B
frames 4
key B
key M
frames 4
key M
key E
frames 4
key E
key O
frames 2
key O
key H
frames 4
key H
key V
key R
frames 4
drag 300 200 420 260 left
frames 4
drag 300 200 260 180 right
scroll 3
frames 4
scroll -3
key 0
key T
frames 4
key G
frames 4
key A
frames 4
key T
key G
frames 4
resize 160 90
key F
frames 2
key F
frames 2
key F
frames 2
key F
frames 2
key F
frames 2
resize 640 360
key P
frames 4
key C
frames 4
resize 1 1
frames 3
resize 2 2
frames 3
resize 3 100
frames 3
resize 3000 2000
frames 3
resize 17 1999
frames 3
resize 1999 17
frames 3
resize 1 1
frames 3
resize 1280 720
frames 3
resize 3000 2000
frames 2
resize 640 360
key C
frames 4
minimize
frames 5
restore
frames 4
key C
minimize
frames 5
restore
frames 4
key C
key 3
frames 40
memory
EOF
}
script=$work/soak.txt
: >"$script"
# Frames drawn per round (none while minimised).
per_round=$(round | awk '$1 == "minimize" { m = 1 } $1 == "restore" { m = 0 }
                         $1 == "frames" && !m { n += $2 } END { print n }')
rounds=$(( (frames + per_round - 1) / per_round ))
for ((i = 0; i < rounds; ++i)); do round >>"$script"; done
echo quit >>"$script"

start=$(date +%s)
status=0
repo=$PWD
(cd "$work" && "$repo/tests/run_with_xvfb.sh" "$binary" view $validate --size 640x360 \
  --script "$script") >"$work/output.txt" 2>&1 || status=$?
elapsed=$(( $(date +%s) - start ))
mapfile -t samples < <(sed -n 's/^view: memory VmRSS \([0-9]*\) kB after \([0-9]*\) frames$/\1 \2/p' "$work/output.txt")
summary() { echo "soak.sh: $*"; }
if [[ $status -ne 0 || ${#samples[@]} -lt 4 ]]; then
  tail -20 "$work/output.txt" >&2
  summary "FAILED: view exited $status after $elapsed s with ${#samples[@]} memory samples"
  exit 1
fi
if grep -qi "validation" "$work/output.txt"; then
  grep -i -m5 "validation" "$work/output.txt" >&2
  summary "FAILED: validation messages"
  exit 1
fi
echo "VmRSS kB after frames:"
printf '  %s\n' "${samples[@]}"
read -r warm_kb warm_frames <<<"${samples[2]}"
read -r end_kb end_frames <<<"${samples[-1]}"
growth=$((end_kb - warm_kb))
peak=$(printf '%s\n' "${samples[@]}" | sort -n | tail -1 | cut -d' ' -f1)
result="$end_frames frames in $elapsed s ($validate): VmRSS $warm_kb kB after warm-up (frame $warm_frames), $end_kb kB at the end, growth $growth kB (limit $max_growth_kb), highest sample $peak kB"
if ((growth >= max_growth_kb)); then
  summary "FAILED: $result"
  exit 1
fi
summary "$result"
