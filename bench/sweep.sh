#!/usr/bin/env bash
# Cost sweep: `raytex bench --json` on the course scene for every size x samples per pixel x
# sphere material (switched as the notes say), one CSV row per configuration, then the plot
# (frame time against pixels and against spp, with linear fits) by bench/sweep_plot.py.
# Usage: bench/sweep.sh [BUILD_DIR]   (default build)
#   writes OUT_DIR/sweep.csv and OUT_DIR/sweep.png; progress goes to stderr.
# Environment: RUNS (default 3); OUT_DIR (default bench/results); SIZES="640x480 1920x1080
#   3840x2160", SPPS="1 4 16", MATERIALS="aSolidChecker aNoise ..." (default all eight) narrow
#   the sweep; RAYTEX=path overrides BUILD_DIR/raytex; PYTHON (default /usr/bin/python3).
# The full sweep is 72 configurations, each RUNS renders of two frames (the first dispatch and a
# timed one): on lavapipe with 2 threads roughly 15-30 minutes, the 3840x2160 spp 16 ones ~1 min each.
set -euo pipefail
set -f  # the lists below are split on spaces, never globbed
src=$(cd "$(dirname "$0")/.." && pwd)
[ $# -le 1 ] || { echo "usage: bench/sweep.sh [BUILD_DIR]   (env: RUNS, OUT_DIR, SIZES, SPPS, MATERIALS, RAYTEX, PYTHON)" >&2; exit 2; }
build=${1:-build}
runs=${RUNS:-3}
out=${OUT_DIR:-$src/bench/results}
raytex=${RAYTEX:-$build/raytex}
python=${PYTHON:-/usr/bin/python3}
sizes=${SIZES:-640x480 1920x1080 3840x2160}
spps=${SPPS:-1 4 16}
all_materials="aSolidChecker aNoise aMarble aWood anImage aTurbulence aDturbulence aChecker"
materials=${MATERIALS:-$all_materials}
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}

die() { echo "sweep.sh: $*" >&2; exit 1; }
[ -x "$raytex" ] || die "no raytex binary at '$raytex' (build it: cmake -S . -B $build -G Ninja &&" \
  "cmake --build $build; or pass BUILD_DIR, or set RAYTEX=path)"
"$raytex" --help 2>&1 | grep -q 'raytex bench' ||
  die "'$raytex' has no 'bench' subcommand (see '$raytex --help'); rebuild it"
[[ $runs =~ ^[1-9][0-9]*$ ]] || die "RUNS must be a positive integer, not '$runs'"
for size in $sizes; do [[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || die "bad size '$size' (want WxH)"; done
for spp in $spps; do [[ $spp =~ ^[1-9][0-9]*$ ]] || die "bad spp '$spp' (want a square number)"; done
for material in $materials; do
  [[ " $all_materials " == *" $material "* ]] || die "unknown material '$material' (one of: $all_materials)"
done
[ -f "$src/bench/sweep_plot.py" ] || die "missing $src/bench/sweep_plot.py"
mkdir -p "$out"
out=$(cd "$out" && pwd)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# The course scene with each material on the sphere.
mkdir -p "$tmp/scenes"
for material in $materials; do
  "$src/scripts/course-scene.sh" "$material" >"$tmp/scenes/$material.cfg"
done

# One `raytex bench --json` output (stdin) -> one CSV row; checks the keys and the size.
to_row() {
  "$python" -c '
import csv, json, sys
material, width, height, spp = sys.argv[1], *map(int, sys.argv[2:5])
text = sys.stdin.read()
try:
    r = json.JSONDecoder().raw_decode(text, text.index("{"))[0]  # the object, over any lines
    m = r["median_ms"]
    if (r["width"], r["height"], r["spp"]) != (width, height, spp):
        sys.exit("asked for %dx%d spp %d, got %sx%s spp %s" % (width, height, spp, r["width"], r["height"], r["spp"]))
    row = [material, width, height, width * height, spp] + ["%.4f" % m[k] for k in
           ("frame", "end_to_end", "pipeline", "first_dispatch", "readback", "encode")] + \
          ["%.4f" % r["mpixel_per_s"], "%.4f" % r["mray_per_s"], r["device"]]
except (ValueError, KeyError, TypeError) as e:  # also: no "{" at all
    sys.exit("no usable JSON object from raytex bench: %r" % e)
csv.writer(sys.stdout, lineterminator="\n").writerow(row)
' "$@"
}

csv=$out/sweep.csv
partial=$csv.partial
echo "material,width,height,pixels,spp,frame_ms,end_to_end_ms,pipeline_ms,first_dispatch_ms,readback_ms,encode_ms,mpixel_per_s,mray_per_s,device" >"$partial"
total=$(($(wc -w <<<"$sizes") * $(wc -w <<<"$spps") * $(wc -w <<<"$materials")))
echo "sweep: $total configurations x $runs runs with $raytex -> $csv" >&2
n=0
start=$SECONDS
for size in $sizes; do
  width=${size%x*} height=${size#*x}
  for spp in $spps; do
    for material in $materials; do
      n=$((n + 1))
      label="[$n/$total] $material ${width}x$height spp $spp"
      if ! json=$("$raytex" bench "$tmp/scenes/$material.cfg" --width "$width" --height "$height" \
                    --spp "$spp" --runs "$runs" --json 2>"$tmp/stderr"); then
        cat "$tmp/stderr" >&2
        die "$label: raytex bench failed; rows so far in $partial"
      fi
      row=$(to_row "$material" "$width" "$height" "$spp" <<<"$json") ||
        die "$label: could not read raytex bench's output: $json"
      echo "$row" >>"$partial"
      IFS=, read -r _ _ _ _ _ frame end _ _ _ _ _ mray _ <<<"$row"
      LC_ALL=C printf '%s: frame %.1f ms, end-to-end %.1f ms, %.1f Mray/s (%d s so far)\n' \
        "$label" "$frame" "$end" "$mray" $((SECONDS - start)) >&2
    done
  done
done
mv "$partial" "$csv"
echo "wrote $csv" >&2
"$python" "$src/bench/sweep_plot.py" "$csv" "$out/sweep.png"
