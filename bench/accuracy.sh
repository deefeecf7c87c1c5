#!/usr/bin/env bash
# The speed-accuracy chart: renders the course scene with each of its eight materials, the
# horizon scene, the bricks scene and the placed Earth with every method and sample count, times them on the GPU and measures their
# error against the float64 reference, then draws docs/accuracy.png, writes docs/accuracy.csv and
# draws the contact sheet of the 1-spp images with their FLIP heat maps, docs/accuracy_sheet.png.
# Usage: bench/accuracy.sh [BUILD_DIR]   (default build; env: WIDTH, HEIGHT, RUNS, default
#        160 120 5; needs python3-matplotlib from Debian; SSIM and FLIP come from raytex diff)
#   writes BUILD_DIR/accuracy/ (the CSV, images and heat maps), docs/accuracy.png,
#   docs/accuracy.csv and docs/accuracy_sheet.png.
set -euo pipefail
[ $# -le 1 ] || { echo "usage: bench/accuracy.sh [BUILD_DIR]   (env: WIDTH, HEIGHT, RUNS)" >&2; exit 2; }
build=$(cd "${1:-build}" && pwd)
cd "$(dirname "$0")/.."
width=${WIDTH:-160} height=${HEIGHT:-120} runs=${RUNS:-5}
for program in raytex_bench_accuracy raytex; do
  [ -x "$build/$program" ] || { echo "accuracy.sh: no $build/$program (build it first)" >&2; exit 1; }
done
out=$build/accuracy
mkdir -p "$out"
scenes=()
variants=()
trap 'rm -f "${variants[@]}"' EXIT
# The course scene with another material on the sphere, switched as the notes say.
for material in aChecker aSolidChecker aNoise aMarble aWood anImage aTurbulence aDturbulence; do
  scene=$(mktemp "${TMPDIR:-/tmp}/raytex-accuracy-XXXXXX.cfg")
  variants+=("$scene")
  scripts/course-scene.sh "$material" >"$scene"
  scenes+=("$material=$scene")
done
scenes+=("horizon=scenes/horizon.cfg" "bricks=scenes/bricks.cfg" "earth=scenes/placed_earth.cfg")
"$build/raytex_bench_accuracy" "$out" "$width" "$height" "$runs" "${scenes[@]}"
/usr/bin/python3 bench/accuracy_chart.py "$out/accuracy.csv" docs/accuracy.png docs/accuracy.csv "$build/raytex"
/usr/bin/python3 bench/contact_sheet.py "$out/accuracy.csv" docs/accuracy_sheet.png "$build/raytex"
