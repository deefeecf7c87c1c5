#!/usr/bin/env bash
# Renders the README's contact sheet: the course scene once per sphere material,
# switched the way the notes say (comment out aSolidChecker, uncomment another), and the scenes
# of the kinds beyond the course.
# Usage: docs/render_gallery.sh [path/to/raytex]   (default build/raytex)
set -euo pipefail
cd "$(dirname "$0")/.."
raytex=${1:-build/raytex}
for material in aSolidChecker aNoise aMarble aWood anImage aTurbulence aDturbulence aChecker; do
  scene=$(mktemp "${TMPDIR:-/tmp}/raytex-gallery-XXXXXX.cfg")
  trap 'rm -f "$scene"' EXIT
  scripts/course-scene.sh "$material" >"$scene"
  "$raytex" render "$scene" -o "docs/images/$material.png" --width 320 --height 240
  rm -f "$scene"
done
# The kinds beyond the course, each with a scene of its own.
for scene in bricks; do
  "$raytex" render "scenes/$scene.cfg" -o "docs/images/$scene.png" --width 320 --height 240
done
echo "wrote docs/images/*.png"
