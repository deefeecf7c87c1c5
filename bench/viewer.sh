#!/usr/bin/env bash
# The viewer's frame rate and material-switch latency on a virtual X display (Xvfb).
# Frames: `raytex view --frames N` renders N frames (accumulation restarting) and prints the
# median frame time: render (GPU timestamps) + present. Switches: keys 1-8 and P pressed one
# by one, key-to-frame-shown time, after the idle viewer has prepared the pipelines
# ("warm"), and with --frames keeping it busy so that it never prepares them ("cold"), with
# Mesa's shader cache disabled. Selection: Tab on the second of two spheres, then keys 2-8 and 1
# put each material on it alone, a combination of kinds the idle viewer has not compiled (the
# all-kinds kernel shows it), key-to-frame-shown time.
# Usage: bench/viewer.sh [BUILD_DIR] [frames|switches|selection|all]   (default build all; env:
#        RUNS, default 3; one line per measurement)
set -u
[ $# -le 2 ] || { echo "usage: bench/viewer.sh [BUILD_DIR] [frames|switches|selection|all]   (env: RUNS)" >&2; exit 2; }
build=${1:-build}
runs=${RUNS:-3}
parts=${2:-all}
case "$parts" in frames|switches|selection|all) ;; *) echo "viewer.sh: the part is frames, switches, selection or all, not '$parts'" >&2; exit 2 ;; esac
src=$(cd "$(dirname "$0")/.." && pwd)
raytex=$(cd "$build" && pwd)/raytex
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export LP_NUM_THREADS=${LP_NUM_THREADS:-2}
tmp=$(mktemp -d)
display=""
for n in $(seq 130 160); do [ -e /tmp/.X11-unix/X$n ] || { display=":$n"; break; }; done
Xvfb "$display" -screen 0 1920x1200x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$tmp"' EXIT
export DISPLAY=$display
for _ in $(seq 50); do xdotool getdisplaygeometry >/dev/null 2>&1 && break; sleep 0.1; done

# The course scene, and the same with aMarble on the sphere.
mkdir -p "$tmp/scenes"
"$src/scripts/course-scene.sh" aSolidChecker >"$tmp/scenes/textures.cfg"
"$src/scripts/course-scene.sh" aMarble >"$tmp/scenes/marble.cfg"
{ cat "$tmp/scenes/textures.cfg"; echo 'sphere { center = (3.2, -1, 0); radius = 1; aSolidChecker; }'; } \
  >"$tmp/scenes/two.cfg"

for size in 640x480 1280x720; do
  [ "$parts" = switches ] || [ "$parts" = selection ] && break
  for scene in textures marble; do
    for _ in $(seq "$runs"); do
      line=$("$raytex" view "$tmp/scenes/$scene.cfg" --width "${size%x*}" --height "${size#*x}" --frames 300 |
        grep frames)
      echo "$scene $line"
    done
  done
done

switches() {  # switches LABEL SETTLE_SECONDS VIEW_ARGS...: press the material keys, print the latency
  local label=$1 settle=$2
  shift 2
  "$raytex" view "$tmp/scenes/textures.cfg" --stats "$@" >"$tmp/switch.log" 2>&1 &
  local viewer=$! wid=""
  for _ in $(seq 600); do wid=$(xdotool search --all --pid "$viewer" --name '^raytex' 2>/dev/null | head -1); [ -n "$wid" ] && break; sleep 0.1; done
  sleep "$settle"
  for key in 2 3 4 5 6 7 8 1 p p p; do
    xdotool key --window "$wid" "$key"
    sleep 0.7
  done
  xdotool key --window "$wid" Escape
  xdotool keyup Escape  # released through the server: the window may be gone (tests/viewer/viewer_test.sh)
  wait "$viewer"
  echo "$label $(grep -h 'switches\|error' "$tmp/switch.log")"
}
# Mesa's shader cache off: the first run on a machine, when every compile is a real one.
export MESA_SHADER_CACHE_DISABLE=true
for _ in $(seq "$runs"); do
  [ "$parts" = frames ] || [ "$parts" = selection ] && break
  switches warm 15
  switches cold 2 --frames 1000000
done

selection() {  # the second sphere (at pixel (513, 269) of 640x480) selected, then 2-8 and 1 on it
  "$raytex" view "$tmp/scenes/two.cfg" --stats >"$tmp/selection.log" 2>&1 &
  local viewer=$! wid=""
  for _ in $(seq 600); do wid=$(xdotool search --all --pid "$viewer" --name '^raytex' 2>/dev/null | head -1); [ -n "$wid" ] && break; sleep 0.1; done
  sleep 15
  xdotool mousemove --window "$wid" 513 269 key --window "$wid" Tab
  sleep 0.5
  for key in 2 3 4 5 6 7 8 1; do
    xdotool key --window "$wid" "$key"
    sleep 0.7
  done
  xdotool key --window "$wid" Escape
  xdotool keyup Escape
  wait "$viewer"
  echo "selection $(grep -h 'switches\|error' "$tmp/selection.log")"
}
for _ in $(seq "$runs"); do
  [ "$parts" = selection ] || [ "$parts" = all ] || break
  selection
done
