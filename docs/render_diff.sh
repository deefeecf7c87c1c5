#!/usr/bin/env bash
# Renders the README's comparison: the default scene with point sampling and with the box filter,
# each against the float64 reference (16 samples a pixel) with raytex diff's FLIP heat map.
# Usage: docs/render_diff.sh [path/to/raytex]   (default build/raytex)
set -euo pipefail
cd "$(dirname "$0")/.."
raytex=${1:-build/raytex}
size=(--width 320 --height 240)
reference=$(mktemp -d "${TMPDIR:-/tmp}/raytex-diff-XXXXXX")
trap 'rm -rf "$reference"' EXIT
"$raytex" render scenes/textures.cfg "${size[@]}" --reference --spp 16 -o "$reference/reference.exr"
for filter in point box; do
  "$raytex" render scenes/textures.cfg "${size[@]}" --filter "$filter" -o "docs/images/diff_$filter.png"
  "$raytex" diff "$reference/reference.exr" "docs/images/diff_$filter.png" --heatmap "docs/images/diff_${filter}_flip.png"
done
