#!/usr/bin/env bash
# raytex against POV-Ray 3.7 at equal quality, on the course scene, one row per sphere material.
#
# Usage: bench/povray/quality.sh [BUILD_DIR]   (default build; env: WIDTH, HEIGHT, RUNS,
#        MATERIALS, OUT, SLOW_MS, CONVERGED_DEPTH; default 640 360 3, all eight materials,
#        BUILD_DIR/povray-quality, 15000, 4)
#
# compare.sh times both renderers at one ray per pixel. This script asks how long each takes to
# reach the same error:
#   - POV-Ray renders each bench/povray/<material>.pov at anti-aliasing settings from off to high
#     (the list below), and its error is measured against its own converged render,
#     +A0.0 +AM2 +R4 -J (a 9 x 9 corner-to-corner grid in every pixel; CONVERGED_DEPTH=5 makes
#     it +R5, a 17 x 17 grid, about four times the work).
#   - raytex renders the course scene with that material (scripts/course-scene.sh) with each
#     texture filter (point, box and coverage at 1, 4, 16, 64 spp), and its error is
#     measured against its own float64 reference (`raytex render --reference`, 64 x 64 samples per
#     pixel).
#   - For raytex's best method at 1 spp (lowest RMSE), of error E and frame time T_r, it finds the
#     time POV-Ray needs to reach E, interpolated in log(time)-log(error) on the lower convex hull
#     of POV-Ray's (time, error) points, and the ratio T_povray / T_r. The same for the mean FLIP
#     (quality_table.py prints the table).
#
# Error: RMSE of linear values and mean LDR-FLIP, both from `raytex diff --json`. POV-Ray writes
# 16-bit sRGB PNGs (+FN16); raytex diff decodes a PNG from sRGB to linear at its full 16 bits
# (docs/outputs.md), so the PNGs are compared as they are. When either image is a PNG both are
# clamped to [0, 1]; raytex's EXR renders and reference are compared unclamped.
#
# Time: POV-Ray's own Trace Time (median of RUNS; resolution 1 ms) against raytex's frame time
# (`raytex bench --json`, median_ms.frame, GPU timestamps of one frame, median of RUNS), as in
# compare.sh. The CSV also holds wall times: the whole povray process, and raytex bench's
# median_ms.end_to_end (one whole render inside the process). A POV-Ray setting whose first
# run traces for longer than SLOW_MS milliseconds is run once.
#
# Written to OUT:
#   quality.csv   every point: material, renderer, setting, time_ms, wall_ms, rmse, flip (each
#                 renderer's error against its own converged image), runs, and rmse_ref,
#                 flip_ref: the error against raytex's float64 reference, for POV-Ray too. That
#                 second yardstick is fair to both only where the two scenes draw the same
#                 pattern (aSolidChecker, aChecker, anImage; the noise kinds differ in detail,
#                 README.md): a second table shows it for those three, the converged render
#                 counting there as one more POV-Ray setting. The "povray-converged"
#                 row holds the converged render's time (one run) and its error against raytex's
#                 reference, "raytex-reference" the reference's wall time.
#   quality.txt   the table printed at the end.
#   ref/, converged/   raytex's reference EXRs and POV-Ray's converged PNGs, reused by later
#                 runs: each name holds a hash of the scene files, the renderer's version, the
#                 size and the options (delete them after changing a renderer without changing
#                 its version).
#
# Sample positions: with -J every POV-Ray setting below traces points of the converged render's
# grid (+AM2 at a lower depth: a sub-grid of it; +AM1 +R2 and +R4: its points at 1/4 and 1/8
# steps) except +AM1 +R3, +R5 and +R6 (thirds, fifths, sixths). Its error against the
# converged render is then the difference of two quadratures on one grid, which can be smaller
# than either's error against the true pixel integral; raytex's reference takes 4096 samples a
# pixel, its renders at most 64.
#
# Threads: POV-Ray runs with +WT$LP_NUM_THREADS (default 2), lavapipe's thread count. For the
# CPU-against-CPU comparison set VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
usage="usage: bench/povray/quality.sh [BUILD_DIR]   \
(env: WIDTH, HEIGHT, RUNS, MATERIALS, OUT, SLOW_MS, CONVERGED_DEPTH)"

die() { echo "quality.sh: $*" >&2; exit 1; }
note() { echo "[$(date +%H:%M:%S)] $*" >&2; }

[ $# -le 1 ] || { echo "$usage" >&2; exit 2; }
case "${1:-}" in -h|--help) echo "$usage"; exit 0 ;; esac
build=${1:-build}
case "$build" in /*) ;; *) build="$PWD/$build" ;; esac
raytex="$build/raytex"
width=${WIDTH:-640}
height=${HEIGHT:-360}
runs=${RUNS:-3}
slow_ms=${SLOW_MS:-15000}
depth=${CONVERGED_DEPTH:-4}
out=${OUT:-$build/povray-quality}
all_materials="aSolidChecker aNoise aMarble aWood anImage aTurbulence aDturbulence aChecker"
read -r -a materials <<<"${MATERIALS:-$all_materials}"

command -v povray >/dev/null 2>&1 || die "povray not found on PATH (Debian: apt-get install povray)"
[ -x "$raytex" ] || die "no raytex binary at $raytex (build it, or pass the build directory)"
python=$(command -v python3 || true)
[ -n "$python" ] || die "python3 not found"
command -v sha256sum >/dev/null 2>&1 || die "sha256sum not found"
for n in "$width" "$height" "$runs" "$slow_ms"; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || die "WIDTH, HEIGHT, RUNS and SLOW_MS must be positive integers (got '$n')"
done
[[ "$depth" =~ ^[3-6]$ ]] || die "CONVERGED_DEPTH must be 3 to 6 (got '$depth')"
[ "${#materials[@]}" -gt 0 ] || die "MATERIALS is empty"
for m in "${materials[@]}"; do
  [[ " $all_materials " == *" $m "* ]] || die "unknown material '$m' (one of: $all_materials)"
  [ -f "$here/$m.pov" ] || die "no POV-Ray scene $here/$m.pov"
done
help=$("$raytex" --help 2>&1 || true)
grep -q 'raytex bench' <<<"$help" || die "this raytex has no 'bench' subcommand"
grep -q -- '--reference' <<<"$help" || die "this raytex has no 'render --reference'"

threads=${LP_NUM_THREADS:-2}
export LP_NUM_THREADS=$threads

# POV-Ray's anti-aliasing settings, from off to high (all with jitter off, so that every run of
# a setting traces the same rays). Method 1 supersamples a pixel that differs from its left or
# top neighbour by at least the threshold (0: every pixel) with an R x R grid of cell centres
# plus the centre ray (R*R + 1 rays: up to 37 at +R6); method 2 subdivides a pixel's
# corner-to-corner grid down to 2^(R-1) + 1 points a side where corners differ by at least the
# threshold. +AM1 +A0.3 +R3 is POV-Ray's +A default. +AM2 stops one depth below the converged
# render's.
pov_settings=(
  "-A"
  "+AM1 +A0.3 +R3 -J"
  "+AM1 +A0.1 +R3 -J"
  "+AM1 +A0.03 +R3 -J"
  "+AM1 +A0.0 +R2 -J"
  "+AM1 +A0.0 +R3 -J"
  "+AM1 +A0.0 +R4 -J"
  "+AM1 +A0.0 +R5 -J"
  "+AM1 +A0.0 +R6 -J"
)
for threshold in 0.3 0.1 0.03 0.0; do
  for ((r = 2; r < depth; r++)); do pov_settings+=("+AM2 +A$threshold +R$r -J"); done
done
pov_converged="+AM2 +A0.0 +R$depth -J"
ref_spp=4096

# raytex's methods: filter and samples per pixel (a raytex that refuses coverage above 1 spp,
# exit 2, skips those).
rt_methods=(
  "point 1" "point 4" "point 16" "point 64"
  "box 1" "box 4" "box 16" "box 64"
  "coverage 1" "coverage 4" "coverage 16" "coverage 64"
)

mkdir -p "$out/ref" "$out/converged" || die "cannot create $out"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/raytex-quality.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

now_ns() { date +%s%N; }
median() {
  "$python" -c "import statistics,sys; print(f'{statistics.median(float(a) for a in sys.argv[1:]):.3f}')" "$@"
}
# Exit status 0 when the number $1 is greater than $2.
greater() { "$python" -c "import sys; sys.exit(0 if float(sys.argv[1]) > float(sys.argv[2]) else 1)" "$1" "$2"; }
hash_of() { cat "$@" | sha256sum | cut -c1-12; }

pov_version=$(povray --version 2>&1 | sed -n 's/^\(POV-Ray [0-9][^ ]*\).*/\1/p' | head -n 1)
rt_version=$("$raytex" --version 2>&1 | head -n 1)

# One POV-Ray render of MATERIAL to a 16-bit PNG with the options given; prints "trace_ms wall_ms".
source "$here/povray_render.sh"
run_povray() {
  local material=$1 png=$2
  shift 2
  povray_render "$material" "$png" +FN16 "$@"
}

# raytex diff A B; prints "rmse flip".
diff_images() {
  local json="$tmp/diff.json"
  "$raytex" diff "$1" "$2" --json >"$json" 2>"$tmp/diff.err" \
    || { cat "$tmp/diff.err" >&2; die "raytex diff failed on $1 and $2"; }
  "$python" -c "import json,sys; d=json.load(open(sys.argv[1])); print(repr(float(d['rmse'])), repr(float(d['flip'])))" \
    "$json"
}

csv="$out/quality.csv"
echo "material,renderer,setting,time_ms,wall_ms,rmse,flip,runs,rmse_ref,flip_ref" >"$csv"
row() { local IFS=,; echo "$*" >>"$csv"; }

note "raytex ($rt_version) vs ${pov_version:-POV-Ray}: ${width}x${height}, median of $runs runs," \
  "$threads threads; writing $out"
t_start=$(now_ns)
load0=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')
for material in "${materials[@]}"; do
  scene="$tmp/$material.cfg"
  "$root/scripts/course-scene.sh" "$material" >"$scene" || die "could not make the $material scene"

  # raytex's float64 reference, cached by scene, raytex version and size. `--reference` takes
  # its samples per pixel from --spp like any render: 4096 is the 64 x 64 grid of docs/accuracy.md.
  key=$( (cat "$scene" "$root/scenes/texture_include.cfg"; echo "$rt_version ${width}x${height} $ref_spp") | hash_of)
  ref="$out/ref/$material-${width}x${height}-$key.exr"
  if [ ! -s "$ref" ]; then
    note "$material: raytex reference (float64, 64x64 samples per pixel)"
    t0=$(now_ns)
    "$raytex" render "$scene" --reference --spp "$ref_spp" --width "$width" --height "$height" -o "$ref" \
      >"$tmp/ref.log" 2>&1 \
      || { cat "$tmp/ref.log" >&2; rm -f "$ref"; die "raytex render --reference failed on $material"; }
    echo $(( ($(now_ns) - t0) / 1000000 )) >"$ref.ms"
  fi
  ref_ms=$(cat "$ref.ms" 2>/dev/null || echo nan)

  # POV-Ray's converged render, cached by scene files, POV-Ray version, size and options.
  key=$( (cat "$here/$material.pov" "$here/course.inc"; echo "$pov_version ${width}x${height} $pov_converged +FN16") \
    | hash_of)
  conv="$out/converged/$material-${width}x${height}-$key.png"
  if [ ! -s "$conv" ]; then
    note "$material: POV-Ray converged render ($pov_converged)"
    read -r -a opts <<<"$pov_converged"
    run_povray "$material" "$tmp/conv.png" "${opts[@]}" >"$tmp/conv.ms"
    mv "$tmp/conv.png" "$conv"
    mv "$tmp/conv.ms" "$conv.ms"
  fi
  read -r conv_trace conv_wall <"$conv.ms"
  read -r e f < <(diff_images "$ref" "$conv")
  row "$material" povray-converged "$pov_converged" "$conv_trace" "$conv_wall" 0 0 1 "$e" "$f"
  row "$material" raytex-reference "--reference --spp $ref_spp (wall time)" "$ref_ms" "$ref_ms" 0 0 1 0 0

  for setting in "${pov_settings[@]}"; do
    read -r -a opts <<<"$setting"
    trace=() wall=()
    for ((run = 0; run < runs; run++)); do
      read -r t w < <(run_povray "$material" "$tmp/pov.png" "${opts[@]}")
      trace+=("$t") wall+=("$w")
      # A slow setting runs once (SLOW_MS).
      if [ "$run" -eq 0 ] && greater "$t" "$slow_ms"; then break; fi
    done
    read -r e f < <(diff_images "$conv" "$tmp/pov.png")
    read -r er fr < <(diff_images "$ref" "$tmp/pov.png")
    row "$material" povray "$setting" "$(median "${trace[@]}")" "$(median "${wall[@]}")" "$e" "$f" "${#trace[@]}" \
      "$er" "$fr"
    note "$material: POV-Ray $setting: $(median "${trace[@]}") ms, RMSE $e, FLIP $f (${#trace[@]} runs)"
  done

  for method in "${rt_methods[@]}"; do
    read -r filter spp <<<"$method"
    exr="$tmp/raytex.exr"
    rm -f "$exr"
    rc=0
    "$raytex" render "$scene" --width "$width" --height "$height" --spp "$spp" --filter "$filter" -o "$exr" \
      >"$tmp/render.log" 2>&1 || rc=$?
    if [ "$rc" -eq 2 ] && [ "$filter" = coverage ]; then
      note "$material: raytex --filter $filter --spp $spp refused, skipped: $(head -n 1 "$tmp/render.log")"
      continue
    fi
    [ "$rc" -eq 0 ] \
      || { cat "$tmp/render.log" >&2; die "raytex render --filter $filter --spp $spp failed on $material"; }
    read -r e f < <(diff_images "$ref" "$exr")
    "$raytex" bench "$scene" --width "$width" --height "$height" --spp "$spp" --filter "$filter" --runs "$runs" --json \
      >"$tmp/bench.json" 2>"$tmp/bench.err" \
      || { cat "$tmp/bench.err" >&2; die "raytex bench --filter $filter --spp $spp failed on $material"; }
    read -r frame e2e device < <("$python" -c "import json,sys; d=json.load(open(sys.argv[1])); m=d['median_ms']
print(m['frame'], m['end_to_end'], d['device'])" "$tmp/bench.json")
    row "$material" raytex "$filter spp$spp" "$frame" "$e2e" "$e" "$f" "$runs" "$e" "$f"
    note "$material: raytex $filter $spp spp: $frame ms, RMSE $e, FLIP $f"
  done
done
total_s=$(( ($(now_ns) - t_start) / 1000000000 ))

{
  echo "raytex vs ${pov_version:-POV-Ray} at equal quality: ${width}x${height}, median of $runs runs, $threads threads"
  echo "raytex: $rt_version on ${device:-?}; error against its float64 reference (64x64 spp)"
  echo "POV-Ray: +WT$threads +FN16; error against its own converged render ($pov_converged)"
  echo
  "$python" "$here/quality_table.py" "$csv"
  echo
  load1=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')
  echo "total run time: ${total_s} s; load average at the start and the end: $load0 / $load1"
  echo "points: $csv"
} | tee "$out/quality.txt"
