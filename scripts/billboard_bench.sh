#!/usr/bin/env bash
# Issue 17's instancing target: 10,000 instanced billboards against 100 of
# the same total area (assets/scenes/billboards-{100,10000}.json, one
# instanced draw each), interleaved in rounds because this machine's speed
# drifts within minutes: each round renders both scenes back to back and
# takes the ratio of their frame times, and the median of the per-round
# ratios is reported, with every round's figures.
#   scripts/billboard_bench.sh [ROUNDS] [SIZE] [SHADELAB_BINARY...]
# Frame time: `render --frames 60`'s device median (the rasteriser's time
# for a frame, from its first to its last timestamp) and its mean wall-clock
# interval between frame completions (which also holds the host's culling
# and the queue's binning, on the same two cores). Needs no display.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
size=${2:-1280x720}
shift $(( $# < 2 ? $# : 2 ))
binaries=("$@")
[ ${#binaries[@]} -eq 0 ] && binaries=(build/release/shadelab)
export VK_DRIVER_FILES="${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results="$work/results"
for round in $(seq "$rounds"); do
  for bin in "${binaries[@]}"; do
    line="$round $bin"
    for count in 100 10000; do
      out=$("$bin" render "assets/scenes/billboards-$count.json" --size "$size" --frames 60 \
              -o "$work/frame.png" 2>&1) || { echo "billboard_bench: $bin failed: $out" >&2; exit 1; }
      device=$(sed -n 's/.*device median \([0-9.]*\) ms.*/\1/p' <<< "$out" | head -1)
      wall=$(sed -n 's/.*wall median [0-9.]* ms, mean \([0-9.]*\) ms.*/\1/p' <<< "$out" | head -1)
      [ -n "$device" ] && [ -n "$wall" ] || { echo "billboard_bench: no timings from $bin" >&2; exit 1; }
      line="$line $device $wall"
    done
    echo "$line" >> "$results"
  done
  echo "round $round of $rounds done" >&2
done
# Columns: round, binary, 100's device and wall ms, 10,000's device and wall ms.
awk '
  function median(list,   n, v, i, j, s) {
    n = split(list, v, " ")
    for (i = 2; i <= n; i++) { s = v[i]; for (j = i - 1; j > 0 && v[j] + 0 > s + 0; j--) v[j+1] = v[j]; v[j+1] = s }
    return n % 2 ? v[(n+1)/2] : (v[n/2] + v[n/2+1]) / 2 }
  BEGIN { printf "%-5s %-28s %9s %9s %7s %9s %9s %7s\n", "round", "binary", "100 dev", "10k dev",
          "ratio", "100 wall", "10k wall", "ratio" }
  { d = $5 / $3; w = $6 / $4
    printf "%-5s %-28s %9.2f %9.2f %7.2f %9.2f %9.2f %7.2f\n", $1, $2, $3, $5, d, $4, $6, w
    dev[$2] = dev[$2] " " d; wall[$2] = wall[$2] " " w
    if (d >= 2) overDev[$2]++; if (w >= 2) overWall[$2]++; n[$2]++ }
  END {
    for (b in n)
      printf "%s: 10,000 / 100 copies, median of %d rounds: device %.2fx (%d rounds at 2x or more), wall %.2fx (%d)\n",
             b, n[b], median(dev[b]), overDev[b] + 0, median(wall[b]), overWall[b] + 0 }' "$results"
