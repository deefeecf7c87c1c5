#!/usr/bin/env bash
# Runs the yardstick benchmark (bench/yardstick.cpp) on lavapipe with 2 threads, the setting
# the project's numbers are measured with: raytex's median frame GPU time against minimal
# hand-written kernels doing the same work, at 1920x1080.
# Usage: bench/yardstick/run.sh [BUILD_DIR] [more raytex_bench_yardstick flags, e.g. --dump DIR]
#        (default build; env: RUNS, default 7)
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
runs=${RUNS:-7}
shift || true
cd "$(dirname "$0")/../.."
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}
exec "$build/raytex_bench_yardstick" --width 1920 --height 1080 --runs "$runs" "$@" scenes/textures.cfg
