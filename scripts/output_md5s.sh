#!/usr/bin/env bash
# Prints the md5 of every image a refactor must keep bit-identical: each
# built-in scene in each shading model, the per-frame options on a few scenes,
# three traces and the default comparison sheet. Run it before and after a
# change and diff the two lists.
#   scripts/output_md5s.sh [BINARY] [DIR]   (defaults: build/release/shadelab, a temp dir)
# RENDER_ARGS is appended to every render and compare (e.g. RENDER_ARGS="--shadows off"
# reproduces the images of a binary from before shadow maps).
set -euo pipefail
binary="${1:-build/release/shadelab}"
dir="${2:-$(mktemp -d)}"
mkdir -p "$dir"
export VK_DRIVER_FILES="${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
scenes=$("$binary" info | sed -n 's/^built-in scenes: *//p')
modes=$("$binary" info | sed -n 's/^shading models: *//p')
render() {  # NAME ARGS...
  local name="$1"; shift
  # shellcheck disable=SC2086  # RENDER_ARGS is a list of words
  "$binary" render "$@" ${RENDER_ARGS:-} -o "$dir/$name.png" >/dev/null
}
for scene in $scenes; do
  for mode in $modes; do render "$scene-$mode" "$scene" --mode "$mode" --size 640x360; done
done
render default-msaa4 default --msaa 4
render default-reversed default --depth reversed
render default-d16 default --depth d16
render bump-off bump --bump off
render env-off env --env off
render env-gouraud-msaa env --mode gouraud --msaa 4
render mip-trilinear mip-plane --filter trilinear
render mip-nearest mip-plane --filter nearest
render mip-tint mip-plane --mip-tint
render teapot-tess4 teapot --tess 4
render teapot-auto teapot --tess auto
render spheres-frames3 spheres --frames 3
for scene in default whitted env; do
  "$binary" trace "$scene" --size 320x180 --spp 4 -o "$dir/trace-$scene.png" >/dev/null
done
"$binary" compare default --size 240x135 ${RENDER_ARGS:-} -o "$dir/compare-default.png" >/dev/null
cd "$dir" && md5sum -- *.png *.json
