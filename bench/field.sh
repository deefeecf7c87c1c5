#!/usr/bin/env bash
# Frame time against the number of spheres: bench/sphere_field.py's fields of N spheres, raytex
# against POV-Ray 3.7, interleaved (one raytex bench and one POV-Ray render per round).
# Prints one line per N: the medians over ROUNDS rounds of raytex's GPU frame
# (`raytex bench --json`, its median over RUNS frames) and of POV-Ray's Trace Time (+WT as
# LP_NUM_THREADS, -A: one ray through each pixel centre, as raytex), and POV-Ray / raytex.
# A scene raytex refuses prints its message instead of a time.
# Usage: bench/field.sh [BUILD_DIR] [N ...]   (env: WIDTH, HEIGHT, ROUNDS, RUNS, SEED;
#        defaults build, N = 8 100 500 5000 50000, 1920x1080, 3 rounds, 3 runs, seed 1)
set -euo pipefail
build=${1:-build}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(8 100 500 5000 50000)
here=$(cd "$(dirname "$0")" && pwd)
width=${WIDTH:-1920} height=${HEIGHT:-1080} rounds=${ROUNDS:-3} runs=${RUNS:-3} seed=${SEED:-1}
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}
raytex=$(cd "$build" && pwd)/raytex
[ -x "$raytex" ] || { echo "field.sh: no $raytex (build it first)" >&2; exit 1; }
command -v povray >/dev/null || { echo "field.sh: needs povray (apt-get install povray)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

raytex_frame() {  # SCENE -> median GPU frame in ms, or "refused: <message>"
  if "$raytex" bench "$1" --width "$width" --height "$height" --runs "$runs" --json >"$tmp/bench.json" 2>"$tmp/bench.err"; then
    sed -n 's/.*"frame": \([0-9.]*\).*/\1/p' "$tmp/bench.json"
  else
    echo "refused: $(head -n 1 "$tmp/bench.err")"
  fi
}

povray_trace() {  # SCENE.pov -> POV-Ray's Trace Time in ms
  (cd "$tmp" && povray "+L$here/povray" "+I$1" "+O$tmp/povray.png" +FN "+W$width" "+H$height" -A \
     "+WT$LP_NUM_THREADS" -D -P >"$tmp/povray.log" 2>&1) || { tail -n 5 "$tmp/povray.log" >&2; exit 1; }
  tr '\r' '\n' <"$tmp/povray.log" | sed -n 's/^ *Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' | tail -n 1 |
    awk '{ printf "%.1f\n", $1 * 1000 }'
}

echo "N, raytex frame ms, POV-Ray trace ms, POV-Ray / raytex (${width}x$height, $LP_NUM_THREADS threads, $rounds rounds)"
for n in "${sizes[@]}"; do
  SEED=$seed OUT_DIR=$tmp python3 "$here/sphere_field.py" "$n"
  : >"$tmp/r" && : >"$tmp/p"
  refused=""
  for _ in $(seq "$rounds"); do
    frame=$(raytex_frame "$tmp/field-$n.cfg")
    case "$frame" in refused:*) refused=$frame ;; *) echo "$frame" >>"$tmp/r" ;; esac
    povray_trace "$tmp/field-$n.pov" >>"$tmp/p"
  done
  p=$(median <"$tmp/p")
  if [ -n "$refused" ]; then
    echo "$n, $refused, $p, -"
  else
    r=$(median <"$tmp/r")
    echo "$n, $r, $p, $(awk -v p="$p" -v r="$r" 'BEGIN { printf "%.2f", p / r }')"
  fi
done
