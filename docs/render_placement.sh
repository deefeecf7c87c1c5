#!/usr/bin/env bash
# Renders the pictures of docs/scene-format.md, "Texture placement": an Earth sphere on a
# uv-grid floor, once without placement and once per placement key, and the README's placed
# Earth (scenes/placed_earth.cfg).
# Usage: docs/render_placement.sh [path/to/raytex]   (default build/raytex)
set -euo pipefail
cd "$(dirname "$0")/.."
raytex=${1:-build/raytex}
scene=$(mktemp "${TMPDIR:-/tmp}/raytex-placement-XXXXXX.cfg")
trap 'rm -f "$scene"' EXIT
root=$(pwd)
# placement NAME SPHERE_KEYS PLANE_KEYS: docs/images/placement-NAME.png
placement() {
  cat >"$scene" <<CFG
camera { eye = (0, 3, 12); lookat = (0, -0.5, 0); up = (0, 1, 0); fov = 35; }
light { position = (-6, 10, 6); color = (1, 1, 1); }
background = (0.05, 0.05, 0.08);
material earth { ambient = (0.25, 0.25, 0.25); diffuse = (0.8, 0.8, 0.8); specular = (0.2, 0.2, 0.2);
                 texture = image { file = "$root/textures/earth.jpg"; }; }
material grid { ambient = (0.2, 0.2, 0.2); specular = (0.1, 0.1, 0.1);
                texture = image { file = "$root/textures/uv_grid.png"; }; }
sphere { center = (0, 0, 0); radius = 2; $2 earth; }
plane { normal = (0, 1, 0); distance = -2; $3 grid; }
CFG
  "$raytex" render "$scene" -o "docs/images/placement-$1.png" --width 200 --height 150 --spp 4 --filter box
}
placement none "" "tex_scale = 4;"
placement rotate "tex_rotate = (0, -90, 23.4);" "tex_scale = 4; tex_rotate = (0, 30, 0);"
placement scale "tex_scale = 0.5;" "tex_scale = 2;"
placement offset "tex_offset = (-0.4, 0, 0);" "tex_scale = 4; tex_offset = (0.5, 0.5, 0);"
"$raytex" render scenes/placed_earth.cfg -o docs/images/placedEarth.png --width 320 --height 240 --spp 4 --filter box
echo "wrote docs/images/placement-*.png and docs/images/placedEarth.png"
