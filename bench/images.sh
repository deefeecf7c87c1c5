#!/usr/bin/env bash
# Frame times of image-textured scenes for two raytex binaries, interleaved: the course scene
# as it is (no image), with anImage on the sphere (1 image), and four spheres with four different images (earth.jpg,
# uv_grid.png and two 1024x512 / 768x768 renders of the course scene made here), point and
# box. Prints one line per scene, filter and binary: the median over ROUNDS rounds of
# `raytex bench --json`'s median GPU frame (RUNS renders each).
# Usage: bench/images.sh BUILD_DIR_A BUILD_DIR_B   (A and B: the two builds' raytex; env: WIDTH,
#        HEIGHT, ROUNDS, RUNS, default 1920 1080 5 3)
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: bench/images.sh BUILD_DIR_A BUILD_DIR_B   (env: WIDTH, HEIGHT, ROUNDS, RUNS)" >&2; exit 2; }
raytex_a=$1/raytex raytex_b=$2/raytex
for raytex in "$raytex_a" "$raytex_b"; do
  [ -x "$raytex" ] || { echo "images.sh: no $raytex (build it first)" >&2; exit 1; }
done
src=$(cd "$(dirname "$0")/.." && pwd)
width=${WIDTH:-1920} height=${HEIGHT:-1080} rounds=${ROUNDS:-5} runs=${RUNS:-3}
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

sed 's|^    aSolidChecker;|    anImage;|' "$src/scenes/textures.cfg" >"$src/scenes/.bench-one-image.cfg"
trap 'rm -rf "$tmp" "$src/scenes/.bench-one-image.cfg"' EXIT
"$raytex_a" render "$src/scenes/textures.cfg" --width 1024 --height 512 -o "$tmp/render-1024x512.png" >/dev/null
"$raytex_a" render "$src/scenes/.bench-one-image.cfg" --width 768 --height 768 -o "$tmp/render-768x768.png" >/dev/null
{
  echo 'camera { eye = (0, 2, 11); lookat = (0, 0, 0); up = (0, 1, 0); fov = 40; }'
  echo 'light { position = (-6, 10, 6); color = (1, 1, 1); }'
  n=0
  for file in "$src/textures/earth.jpg" "$src/textures/uv_grid.png" "$tmp/render-1024x512.png" \
    "$tmp/render-768x768.png"; do
    echo "material m$n { texture = image { file = \"$file\"; }; }"
    echo "sphere { center = ($((n * 3 - 4)).5, 0, 0); radius = 1.4; m$n; }"
    n=$((n + 1))
  done
  echo 'plane { normal = (0, 1, 0); distance = -1.4; }'
} >"$tmp/four-images.cfg"

frame() {  # RAYTEX SCENE FILTER -> the median GPU frame in ms
  "$1" bench "$2" --width "$width" --height "$height" --filter "$3" --runs "$runs" --json |
    sed -n 's/.*"frame": \([0-9.]*\).*/\1/p'
}
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

cp "$src/scenes/textures.cfg" "$src/scenes/.bench-no-image.cfg"
trap 'rm -rf "$tmp" "$src/scenes/.bench-one-image.cfg" "$src/scenes/.bench-no-image.cfg"' EXIT
for scene in "$src/scenes/.bench-no-image.cfg" "$src/scenes/.bench-one-image.cfg" "$tmp/four-images.cfg"; do
  for filter in point box; do
    : >"$tmp/a" && : >"$tmp/b"
    for _ in $(seq "$rounds"); do
      frame "$raytex_a" "$scene" "$filter" >>"$tmp/a"
      frame "$raytex_b" "$scene" "$filter" >>"$tmp/b"
    done
    name=$(basename "$scene" .cfg)
    echo "${name#.bench-} $filter ${width}x$height: A $(median <"$tmp/a") ms ($(tr '\n' ' ' <"$tmp/a")),"\
      "B $(median <"$tmp/b") ms ($(tr '\n' ' ' <"$tmp/b"))"
  done
done
