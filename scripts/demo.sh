#!/usr/bin/env bash
# README command 1: set up, build, and run the main job on the built-in
# default scene, writing one image per shading model, the ray-traced
# reference, the comparison sheet and the speed/accuracy charts into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release
export VK_DRIVER_FILES="${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
bin=build/release/shadelab
mkdir -p out
"$bin" info
for mode in flat gouraud phong blinn-phong; do
  "$bin" render --mode "$mode" --size 1280x720 -o "out/default-$mode.png"
done
"$bin" trace --size 1280x720 -o out/default-trace.png
"$bin" compare -o out/compare.png
# Speed against accuracy: few frames and one round keep the demo short (about
# half a minute on 2 cores); without them bench measures 60 frames x 2 rounds.
"$bin" bench -o out/bench --size 640x360 --frames 12 --rounds 1
"$bin" study zfight -o out/zfight
echo "demo: images written to out/"
