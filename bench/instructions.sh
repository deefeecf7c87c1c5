#!/usr/bin/env bash
# x86 instructions the kernel executes per pixel on lavapipe: raytex_bench_frames under
# valgrind's callgrind with 0 and 2 extra frames, the difference over 2 frames and the pixels.
# One thread and Mesa's shader cache off, so both runs compile alike. Deterministic: use it to
# compare kernel variants on a shared machine, where frame times move by 30 % with the load.
# Needs valgrind (apt-get install valgrind); about 15 s per scene at 320x240.
# Usage: bench/instructions.sh BUILD_DIR SCENE...   (env: WIDTH, HEIGHT, default 320 240; SIDE =
# samples per side, default 1; UNBAKED=1: the kernel that reads the scene from its uniform blocks,
# as the viewer's does; FILTER=box: the box-filtered kernel, as --filter box; PROGRESSIVE=1: the
# viewer's kernel, one sample per frame, accumulated; TILES=0: the scene's one kernel, not tile
# kernels)
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: bench/instructions.sh BUILD_DIR SCENE...   (env: WIDTH, HEIGHT, SIDE, UNBAKED, FILTER, PROGRESSIVE, TILES)" >&2; exit 2; }
build=$1
shift
frames=$build/raytex_bench_frames
[ -x "$frames" ] || { echo "instructions.sh: no $frames (build it first)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=1 MESA_SHADER_CACHE_DISABLE=true
width=${WIDTH:-320} height=${HEIGHT:-240} side=${SIDE:-1}
baked=$([ "${UNBAKED:-0}" = 1 ] && echo unbaked || echo baked)
filter=${FILTER:-point}
mode=$([ "${PROGRESSIVE:-0}" = 1 ] && echo progressive || echo single)
tiles=$([ "${TILES:-1}" = 0 ] && echo one || echo tiles)
case "$filter" in point|box) ;; *) echo "instructions.sh: FILTER must be point or box" >&2; exit 1 ;; esac
count() {  # SCENE FRAMES -> total instructions of the process
  valgrind --tool=callgrind --smc-check=all --callgrind-out-file=/dev/null \
    "$frames" "$1" "$width" "$height" "$2" "$side" "$baked" "$filter" "$mode" "$tiles" 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
for scene in "$@"; do
  base=$(count "$scene" 0)
  more=$(count "$scene" 2)
  echo "$scene ${width}x$height, $((side * side)) spp, $baked, $filter, $mode, $tiles: $(((more - base) / 2 / (width * height))) instructions/pixel"
done
