#!/usr/bin/env bash
# Peak memory and time of `raytex diff` on two large images: renders of scenes/textures.cfg at
# SIDE x SIDE with --filter point and --filter box, in each format named, compared with
# `raytex diff A B --heatmap H` RUNS times under /usr/bin/time. Prints one line per format: the
# pixels, the median wall, user and system seconds, and the largest maximum resident set size,
# in MB and in bytes per pixel.
# Usage: bench/diff.sh [BUILD_DIR] [FORMAT ...]   (FORMAT: png (8-bit, the default), png16,
#        exr or pfm; env: SIDE=4700 (22.09 Mpixel, near the largest input diff reads), RUNS=3)
set -euo pipefail
build=${1:-build}
[ $# -gt 0 ] && shift
formats=${*:-png}
raytex=$build/raytex
[ -x "$raytex" ] || { echo "diff.sh: no $raytex (build it first)" >&2; exit 1; }
src=$(cd "$(dirname "$0")/.." && pwd)
side=${SIDE:-4700} runs=${RUNS:-3}
[ -x /usr/bin/time ] || { echo "diff.sh: needs /usr/bin/time (GNU time)" >&2; exit 1; }
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for format in $formats; do
  case $format in
    png | png16 | exr | pfm) ;;
    *) echo "diff.sh: unknown format '$format' (png, png16, exr or pfm)" >&2; exit 2 ;;
  esac
done
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

for format in $formats; do
  case $format in
    png) ext=png options=() ;;
    png16) ext=png options=(--depth 16) ;;
    exr | pfm) ext=$format options=() ;;
  esac
  for filter in point box; do
    "$raytex" render "$src/scenes/textures.cfg" --width "$side" --height "$side" --filter "$filter" \
      "${options[@]}" -o "$tmp/$filter.$ext" >/dev/null
  done
  : >"$tmp/runs"
  for _ in $(seq "$runs"); do
    /usr/bin/time -o "$tmp/time" -f "%e %U %S %M" "$raytex" diff "$tmp/point.$ext" "$tmp/box.$ext" \
      --heatmap "$tmp/heat.png" >/dev/null
    cat "$tmp/time" >>"$tmp/runs"
  done
  pixels=$((side * side))
  peak_kb=$(awk '{ print $4 }' "$tmp/runs" | sort -n | tail -1)
  echo "$format ${side}x$side ($pixels pixels): wall $(awk '{ print $1 }' "$tmp/runs" | median) s," \
    "user $(awk '{ print $2 }' "$tmp/runs" | median) s, system $(awk '{ print $3 }' "$tmp/runs" | median) s," \
    "peak $(awk -v k="$peak_kb" 'BEGIN { printf "%.0f", k * 1024 / 1e6 }') MB" \
    "($(awk -v k="$peak_kb" -v p="$pixels" 'BEGIN { printf "%.1f", k * 1024 / p }') bytes a pixel)"
  rm -f "$tmp"/point.* "$tmp"/box.*
done
