#!/usr/bin/env bash
# Prints scenes/textures.cfg with MATERIAL on the sphere, switched as the notes say (comment out
# aSolidChecker, uncomment MATERIAL), and with its #include made absolute, so that the copy works
# from any directory.
# Usage: scripts/course-scene.sh MATERIAL > FILE.cfg
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
material=${1:?usage: course-scene.sh MATERIAL}
case $material in
  aSolidChecker) switch=() ;;
  *) switch=(-e 's|^    aSolidChecker;|    // aSolidChecker;|' -e "s|^    // $material;|    $material;|") ;;
esac
scene=$(sed -e "s|^#include \"texture_include.cfg\"|#include \"$root/scenes/texture_include.cfg\"|" \
  "${switch[@]}" "$root/scenes/textures.cfg")
if ! grep -q "^    $material;" <<<"$scene" || ! grep -q "^#include \"$root/" <<<"$scene"; then
  echo "course-scene.sh: cannot put '$material' on the sphere of scenes/textures.cfg" >&2
  exit 2
fi
printf '%s\n' "$scene"
