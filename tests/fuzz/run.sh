#!/usr/bin/env bash
# Builds the parser's fuzz target with clang (RAYTEX_FUZZ=ON: libFuzzer, ASan, UBSan) in
# BUILD_DIR and runs it for SECONDS on a seed corpus of scenes/ and tests/malformed/, with the
# scene keywords as a dictionary. Fails on any finding: a crash, an exception other than a
# located SceneError, undefined behaviour, a leak, an input taking over 10 s, or over 2 GB.
# Findings are kept in BUILD_DIR/findings (replay one: BUILD_DIR/tests/fuzz/raytex_fuzz_parser FILE).
# Usage: tests/fuzz/run.sh [BUILD_DIR] [SECONDS]   (default build/fuzz, 60)
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$src/build/fuzz}
seconds=${2:-60}
command -v clang++ >/dev/null || { echo "run.sh: needs clang++ (apt-get install clang)" >&2; exit 1; }
cmake -S "$src" -B "$build" -G Ninja -DRAYTEX_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target raytex_fuzz_parser
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp "$src"/scenes/*.cfg "$src"/tests/malformed/*.cfg "$corpus"/
mkdir -p "$build/findings"
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1
"$build/tests/fuzz/raytex_fuzz_parser" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -dict="$src/tests/fuzz/scene.dict" -artifact_prefix="$build/findings/" -print_final_stats=1 "$corpus"
