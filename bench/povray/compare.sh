#!/usr/bin/env bash
# raytex against POV-Ray 3.7 on the course scene, one row per sphere material.
#
# Usage: bench/povray/compare.sh [BUILD_DIR]   (default build; env: WIDTH, HEIGHT, SPP, RUNS,
#        default 1920 1080 1 3)
#
# For each material (aSolidChecker ... aChecker) it renders scenes/textures.cfg with that
# material on the sphere (scripts/course-scene.sh) with raytex, and the matching
# bench/povray/<material>.pov with POV-Ray, at the same size and samples per pixel, RUNS times
# each, and prints the medians:
#   - POV-Ray's own Trace Time (from its render statistics) against raytex's per-frame time
#     (`raytex bench --json`: median_ms.frame, the GPU timestamps of one frame);
#   - the wall time of each whole process, start to PNG written: `povray ...` against
#     `raytex render ...`.
# Ratios are POV-Ray / raytex (above 1: raytex is faster).
#
# Set COMPARE_KEEP=DIR to keep the last PNG of each renderer per material in DIR
# (<material>.raytex.png, <material>.povray.png), to compare them by eye.
#
# Threads: POV-Ray runs with +WT$LP_NUM_THREADS (default 2), the thread count of lavapipe, Mesa's
# CPU Vulkan driver. raytex takes the device it would take anyway (a GPU if there is one); for the
# CPU-against-CPU comparison set VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json.
#
# Anti-aliasing (POV-Ray 3.7 tracing options; the code is TraceTask::NonAdaptiveSupersamplingM1
# and SupersampleOnePixel in source/backend/render/tracetask.cpp):
#   SPP 1:      -A, one ray through each pixel centre, as raytex.
#   SPP k*k:    +AM1 +A0.0 +Rk -J. Sampling_Method 1 (non-adaptive) traces each pixel's centre,
#               and supersamples a pixel whose colour differs from its left or top neighbour by
#               at least Antialias_Threshold: with threshold 0 that is every pixel. A supersampled
#               pixel gets a k x k grid (Antialias_Depth = k) at the centres of its k x k sub-cells
#               -- raytex's stratified positions -- and, with jitter off (-J), exactly there. The
#               pixel is the mean of the k*k grid samples and its centre sample: k*k + 1 rays
#               (5 for SPP 4, 17 for SPP 16) where raytex traces k*k. No POV-Ray 3.7 setting gives
#               exactly k*k box-filtered rays: Sampling_Method 2 with threshold 0 traces a
#               (2^(R-1) + 1)^2 grid from corner to corner of each pixel (6 rays a pixel at +R2,
#               22 at +R3) and weights it as a tent. POV-Ray also traces, per 32 x 32 block, one
#               row and one column of its neighbours' centres to compare against (6 % more
#               centre rays).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

[ $# -le 1 ] || { echo "usage: bench/povray/compare.sh [BUILD_DIR]   (env: WIDTH, HEIGHT, SPP, RUNS, COMPARE_KEEP)" >&2; exit 2; }
build=${1:-build}
width=${WIDTH:-1920}
height=${HEIGHT:-1080}
spp=${SPP:-1}
runs=${RUNS:-3}
case "$build" in /*) ;; *) build="$PWD/$build" ;; esac
raytex="$build/raytex"

die() { echo "compare.sh: $*" >&2; exit 1; }

command -v povray >/dev/null 2>&1 || die "povray not found on PATH (Debian: apt-get install povray)"
[ -x "$raytex" ] || die "no raytex binary at $raytex (build it, or pass the build directory)"
python=$(command -v python3 || true)
[ -n "$python" ] || die "python3 not found"
for n in "$width" "$height" "$spp" "$runs"; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || die "WIDTH, HEIGHT, SPP and RUNS must be positive integers (got '$n')"
done

# POV-Ray anti-aliasing for SPP = k*k (see above).
k=$("$python" -c "import math,sys; n=int(sys.argv[1]); r=math.isqrt(n); print(r if r*r==n else 0)" "$spp")
[ "$k" -gt 0 ] || die "SPP must be a square number (1, 4, 9, 16, ...), got $spp"
if [ "$k" -eq 1 ]; then
  pov_aa=(-A)
else
  [ "$k" -le 9 ] || die "SPP $spp: POV-Ray's Antialias_Depth goes up to 9 (SPP 81)"
  pov_aa=(+AM1 +A0.0 "+R$k" -J)
fi

threads=${LP_NUM_THREADS:-2}
export LP_NUM_THREADS=$threads

# `raytex bench` gives the per-frame GPU time; older builds have only `render --stats`.
have_bench=0
if "$raytex" --help 2>&1 | grep -q 'raytex bench'; then have_bench=1; fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/raytex-povray.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

now_ns() { date +%s%N; }
median() { "$python" -c "import statistics,sys; print(statistics.median(float(a) for a in sys.argv[1:]))" "$@"; }

# The course scene with MATERIAL on the sphere (scripts/course-scene.sh).
make_scene() {
  "$root/scripts/course-scene.sh" "$1" >"$2" || die "could not make the $1 scene"
}

# One POV-Ray render at the SPP's anti-aliasing; prints "trace_ms wall_ms".
source "$here/povray_render.sh"
run_povray() { povray_render "$1" "$tmp/povray.png" +FN "${pov_aa[@]}"; }

# One raytex render process; prints "wall_ms render_ms" (render_ms: the --stats render phase,
# which includes lavapipe's shader compile at the first dispatch; the fallback frame time).
run_raytex() {
  local scene=$1 log="$tmp/raytex.log" png="$tmp/raytex.png" t0 t1
  rm -f "$png"
  t0=$(now_ns)
  if ! "$raytex" render "$scene" -o "$png" --width "$width" --height "$height" --spp "$spp" --stats >"$log" 2>&1; then
    cat "$log" >&2
    die "raytex render failed on $scene"
  fi
  t1=$(now_ns)
  [ -s "$png" ] || die "raytex wrote no PNG"
  local render
  render=$(sed -n 's/.*render \([0-9.]*\) ms.*/\1/p' "$log" | tail -n 1)
  echo "$(( (t1 - t0) / 1000 )) ${render:-nan}" | awk '{ printf "%.3f %s\n", $1 / 1000, $2 }'
}

# raytex bench: prints "frame_ms device_name".
run_raytex_bench() {
  local scene=$1 json="$tmp/bench.json"
  if ! "$raytex" bench "$scene" --width "$width" --height "$height" --spp "$spp" --runs "$runs" --json >"$json" 2>"$tmp/bench.err"; then
    cat "$tmp/bench.err" >&2
    die "raytex bench failed on $scene"
  fi
  "$python" -c "import json,sys; d=json.load(open(sys.argv[1])); print(f\"{d['median_ms']['frame']:.3f}\", d['device'])" "$json"
}

materials=(aSolidChecker aNoise aMarble aWood anImage aTurbulence aDturbulence aChecker)

pov_version=$(povray --version 2>&1 | sed -n 's/^\(POV-Ray [0-9][^ ]*\).*/\1/p' | head -n 1)
device="?"
echo "raytex vs ${pov_version:-POV-Ray}: ${width}x${height}, ${spp} spp, median of ${runs} runs, ${threads} threads"
echo "POV-Ray: +WT$threads ${pov_aa[*]}; raytex: --spp $spp"
if [ "$have_bench" -eq 0 ]; then
  echo "note: this raytex has no 'bench' subcommand; raytex frame = 'render --stats' render phase (includes the shader compile)"
fi

rows=()
for material in "${materials[@]}"; do
  scene="$tmp/$material.cfg"
  make_scene "$material" "$scene"
  pov_trace=() pov_wall=() rt_wall=() rt_render=()
  for ((run = 0; run < runs; run++)); do  # alternated, so both see the same machine load
    out=$(run_povray "$material")
    pov_trace+=("${out% *}") pov_wall+=("${out#* }")
    out=$(run_raytex "$scene")
    rt_wall+=("${out% *}") rt_render+=("${out#* }")
  done
  if [ "$have_bench" -eq 1 ]; then
    out=$(run_raytex_bench "$scene")
    rt_frame=${out%% *} device=${out#* }
  else
    rt_frame=$(median "${rt_render[@]}")
  fi
  if [ -n "${COMPARE_KEEP:-}" ]; then
    mkdir -p "$COMPARE_KEEP"
    cp "$tmp/raytex.png" "$COMPARE_KEEP/$material.raytex.png"
    cp "$tmp/povray.png" "$COMPARE_KEEP/$material.povray.png"
  fi
  rows+=("$material $(median "${pov_trace[@]}") $rt_frame $(median "${pov_wall[@]}") $(median "${rt_wall[@]}")")
done

[ "$have_bench" -eq 1 ] && echo "raytex device: $device"
echo
"$python" - "${rows[@]}" <<'EOF'
import sys
head = ("material", "POV trace ms", "raytex frame ms", "ratio", "POV wall ms", "raytex wall ms", "ratio")
print("%-14s %13s %16s %7s %12s %15s %7s" % head)
for row in sys.argv[1:]:
    m, pt, rf, pw, rw = row.split()
    pt, rf, pw, rw = map(float, (pt, rf, pw, rw))
    ratio = lambda a, b: "%7.1f" % (a / b) if b > 0 else "%7s" % "-"
    print("%-14s %13.1f %16.1f %s %12.1f %15.1f %s" % (m, pt, rf, ratio(pt, rf), pw, rw, ratio(pw, rw)))
EOF
