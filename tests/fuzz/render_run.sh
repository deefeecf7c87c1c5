#!/usr/bin/env bash
# Builds the render fuzz target with clang (RAYTEX_FUZZ_RENDER=ON: libFuzzer) in BUILD_DIR and
# runs it for SECONDS on lavapipe, on a seed corpus of scenes/, tests/malformed/ and
# tests/fuzz/render_seeds/ (scenes with extreme values), with the scene keywords as a
# dictionary. Fails on any finding: a non-finite pixel, a crash, an input taking over 10 s.
# Findings are kept in BUILD_DIR/findings (replay one: BUILD_DIR/tests/fuzz/raytex_fuzz_render FILE).
# Usage: tests/fuzz/render_run.sh [BUILD_DIR] [SECONDS]   (default build/fuzz-render, 30)
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$src/build/fuzz-render}
seconds=${2:-30}
command -v clang++ >/dev/null || { echo "render_run.sh: needs clang++ (apt-get install clang)" >&2; exit 1; }
cmake -S "$src" -B "$build" -G Ninja -DRAYTEX_FUZZ_RENDER=ON -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target raytex_fuzz_render
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp "$src"/scenes/*.cfg "$src"/tests/malformed/*.cfg "$src"/tests/fuzz/render_seeds/*.cfg "$corpus"/
mkdir -p "$build/findings"
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}
"$build/tests/fuzz/raytex_fuzz_render" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -dict="$src/tests/fuzz/scene.dict" -artifact_prefix="$build/findings/" -print_final_stats=1 "$corpus"
