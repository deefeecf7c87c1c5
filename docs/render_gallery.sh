#!/usr/bin/env bash
# Renders the README's contact sheet: the course scene once per sphere material,
# switched the way the notes say (comment out aSolidChecker, uncomment another).
# Usage: docs/render_gallery.sh [path/to/raytex]   (default build/raytex)
set -euo pipefail
cd "$(dirname "$0")/.."
raytex=${1:-build/raytex}
for material in aSolidChecker aNoise aMarble aWood anImage aTurbulence aDturbulence aChecker; do
  scene=$(mktemp scenes/.gallery-XXXXXX.cfg)  # beside textures.cfg so its #include resolves
  trap 'rm -f "$scene"' EXIT
  if [ "$material" = aChecker ]; then
    sed 's|^    aSolidChecker;|    aChecker;|' scenes/textures.cfg >"$scene"
  else
    sed -e 's|^    aSolidChecker;|    // aSolidChecker;|' -e "s|^    // $material;|    $material;|" \
      scenes/textures.cfg >"$scene"
  fi
  "$raytex" render "$scene" -o "docs/images/$material.png" --width 320 --height 240
  rm -f "$scene"
done
echo "wrote docs/images/*.png"
