#!/usr/bin/env bash
# Builds a fuzz target with clang in BUILD_DIR and runs it for SECONDS on a seed corpus of
# scenes/ and tests/malformed/, with the scene keywords as a dictionary:
# - parser (RAYTEX_FUZZ=ON: libFuzzer, ASan, UBSan): every input parses or throws a located
#   SceneError; a crash, another exception, undefined behaviour, a leak, an input taking over
#   10 s or over 2 GB is a finding. Default BUILD_DIR build/fuzz, 60 s.
# - render (RAYTEX_FUZZ_RENDER=ON: libFuzzer only), on lavapipe, seeded with
#   tests/fuzz/render_seeds/ too (scenes with extreme values): every input that parses renders
#   finite pixels with both filters; a non-finite pixel, a crash or an input taking over 10 s
#   is a finding. Default BUILD_DIR build/fuzz-render, 30 s.
# Findings are kept in BUILD_DIR/findings (replay one: BUILD_DIR/tests/fuzz/raytex_fuzz_TARGET FILE).
# Usage: tests/fuzz/run.sh [parser|render] [BUILD_DIR] [SECONDS]
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
target=${1:-parser}
case "$target" in
  parser) option=RAYTEX_FUZZ build=${2:-$src/build/fuzz} seconds=${3:-60} rss=2048 seeds= ;;
  render) option=RAYTEX_FUZZ_RENDER build=${2:-$src/build/fuzz-render} seconds=${3:-30} rss=4096
          seeds=$src/tests/fuzz/render_seeds
          export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
          export LP_NUM_THREADS=${LP_NUM_THREADS:-2} ;;
  *) echo "run.sh: the target is parser or render, got '$target'" >&2; exit 2 ;;
esac
command -v clang++ >/dev/null || { echo "run.sh: needs clang++ (apt-get install clang)" >&2; exit 1; }
# -O1 with line tables, as libFuzzer's documentation suggests: quick to build, enough for stacks.
cmake -S "$src" -B "$build" -G Ninja -D$option=ON -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" >/dev/null
cmake --build "$build" --target raytex_fuzz_$target
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp "$src"/scenes/*.cfg "$src"/tests/malformed/*.cfg ${seeds:+"$seeds"/*.cfg} "$corpus"/
mkdir -p "$build/findings"
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1
# A unit over 30 s is a hang; a pipeline compile on a loaded machine takes over 10 s.
"$build/tests/fuzz/raytex_fuzz_$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=$rss \
  -dict="$src/tests/fuzz/scene.dict" -artifact_prefix="$build/findings/" -print_final_stats=1 "$corpus"
