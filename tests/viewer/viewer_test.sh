#!/usr/bin/env bash
# The viewer under Xvfb (a virtual X display) with lavapipe: keys switch the sphere's and
# the plane's materials (read back from the window title), and the screenshot key writes
# the same PNG as raytex render for the same scene and size.
# Usage: viewer_test.sh RAYTEX SOURCE_DIR XWD_DIFF
set -u
raytex=$1
src=$2
xwdDiff=$3
for tool in Xvfb xdotool xwd; do
  command -v $tool >/dev/null || { echo "FAIL: $tool not installed (apt-get install xvfb xdotool x11-apps)"; exit 1; }
done
tmp=$(mktemp -d)
display=""
for n in $(seq 90 120); do [ -e /tmp/.X11-unix/X$n ] || { display=":$n"; break; }; done
# -noreset: the server does not reset when its last client leaves, so a viewer started just
# after another exits finds the display (a reset in between refused it: "no display").
Xvfb "$display" -screen 0 800x600x24 -noreset >/dev/null 2>&1 &
xvfb=$!
viewer=""
cleanup() {
  [ -n "$viewer" ] && kill "$viewer" 2>/dev/null
  kill "$xvfb" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
export DISPLAY=$display
passed=0
failed=0
check() {  # check NAME CONDITION...
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL $name"; fi
}
for _ in $(seq 50); do xdotool getdisplaygeometry >/dev/null 2>&1 && break; sleep 0.1; done
# waitWindow LOG CHECK: sets wid to the viewer's window, up to a minute (with validation
# layers, under load or under the sanitizers start-up is slow); without one, nothing else can
# be checked: the viewer's last output lines, and exit.
waitWindow() {
  wid=""
  log=$1
  for _ in $(seq 600); do
    wid=$(xdotool search --all --pid "$viewer" --name '^raytex' 2>/dev/null | head -1)
    [ -n "$wid" ] && break
    kill -0 "$viewer" 2>/dev/null || break
    sleep 0.1
  done
  if [ -z "$wid" ]; then
    echo "FAIL $2; the viewer's output:"
    tail -20 "$1"
    exit 1
  fi
  check "$2" test -n "$wid"
}
# startViewer LOG CHECK ARGS...: raytex view ARGS --validate, its output in LOG, and its window.
startViewer() {
  local output=$1 name=$2
  shift 2
  "$raytex" view "$@" --validate >"$output" 2>&1 &
  viewer=$!
  waitWindow "$output" "$name"  # sets the global log viewerGone prints
}

startViewer "$tmp/view.log" window-opens "$src/scenes/textures.cfg" -o "$tmp/shot.png" --width 320 --height 240
title() { xdotool getwindowname "$wid"; }
# viewerGone: the viewer has exited; its last output lines are printed once, and the checks
# that wait on its window fail at once instead of each waiting out its time.
viewerGone() {
  [ -n "$viewer" ] && kill -0 "$viewer" 2>/dev/null && return 1
  if [ -z "${goneReported:-}" ]; then
    goneReported=1
    wait "$viewer"
    echo "the viewer exited (status $?); its output:"
    tail -20 "$log"
  fi
  return 0
}
waitTitle() {  # waitTitle PATTERN: the title matches within 30 s (a loaded machine, the sanitizers)
  for _ in $(seq 300); do
    viewerGone && return 1
    title 2>/dev/null | grep -q -- "$1" && return 0
    sleep 0.1
  done
  echo "title: $(title 2>&1)"
  return 1
}
keyThenTitle() {  # keyThenTitle CHECK KEY PATTERN: KEY, then the title matches PATTERN
  xdotool key --window "$wid" "$2"
  check "$1" waitTitle "$3"
}
waitTitleGone() {  # waitTitleGone PATTERN: the title stops matching within 30 s
  for _ in $(seq 300); do
    viewerGone && return 1
    title 2>/dev/null | grep -q -- "$1" || return 0
    sleep 0.1
  done
  echo "title: $(title 2>&1)"
  return 1
}
# stopViewer [KEY]: Escape (or KEY: q), then the viewer's exit status within 30 s (killed and
# 124 after that).
# xdotool presses a key of the focused window through the server (XTEST) but sends its release
# to the window, which may be gone by then: the server then holds Escape down, and its
# autorepeat closes the next viewer as it opens. So Escape is released through the server too.
stopViewer() {
  if viewerGone; then
    rc=1
  else
    xdotool key --window "$wid" "${1:-Escape}" 2>/dev/null
    xdotool keyup "${1:-Escape}" 2>/dev/null
    for _ in $(seq 300); do kill -0 "$viewer" 2>/dev/null || break; sleep 0.1; done
    local killed=0
    kill -0 "$viewer" 2>/dev/null && { kill -9 "$viewer"; killed=1; }
    wait "$viewer"
    rc=$?
    [ "$killed" -eq 1 ] && rc=124
  fi
  viewer=""
  goneReported=""
}
check initial-materials waitTitle 'sphere: aSolidChecker | plane: aChecker'
check accumulates waitTitle '| 64/64 samples'
keyThenTitle key-3-marble 3 'sphere: aMarble'
keyThenTitle key-p-plane p 'plane: aSolidChecker'
keyThenTitle key-p-cycles p 'plane: aNoise'
keyThenTitle key-5-image 5 'sphere: anImage | plane: aNoise'
keyThenTitle screenshot F12 "wrote $tmp/shot.png"
cp "$tmp/shot.png" "$tmp/first.png"
# Orbit away: the frame changes; R resets: the frame is the scene file's view again.
waitShot() {  # waitShot: F12, then the new file appears
  rm -f "$tmp/shot.png"
  xdotool key --window "$wid" F12
  for _ in $(seq 300); do
    [ -s "$tmp/shot.png" ] && return 0
    viewerGone && return 1
    sleep 0.1
  done
  return 1
}
xdotool key --window "$wid" d d w
sleep 0.5
check orbit-screenshot waitShot
check orbit-changes-view bash -c "! cmp -s '$tmp/shot.png' '$tmp/first.png'"
xdotool key --window "$wid" r
sleep 0.5
check reset-screenshot waitShot
check reset-restores-view cmp -s "$tmp/shot.png" "$tmp/first.png"
cp "$tmp/first.png" "$tmp/shot.png"
# What the window shows once converged: the kernel's 8-bit display pixels (an approximate
# sRGB curve, so within 1 of the PNG), compared with the headless render below.
check window-converged waitTitle '| 64/64 samples'
xwd -id "$wid" -silent >"$tmp/window.xwd"
stopViewer
check clean-exit test "$rc" -eq 0
check no-validation-errors test "$(grep -c 'validation error' "$tmp/view.log")" -eq 0

# The same view headless: the sphere and plane materials switched in a copy of the scene file
# (beside its include and the textures, as in scenes/, under the temporary directory).
mkdir -p "$tmp/headless/scenes"
cp "$src/scenes/texture_include.cfg" "$tmp/headless/scenes/"
ln -s "$src/textures" "$tmp/headless/textures"
sed -e 's|^    aSolidChecker;|    // aSolidChecker;|' -e 's|^    // anImage;|    anImage;|' \
  -e 's|^    aChecker;|    aNoise;|' "$src/scenes/textures.cfg" >"$tmp/headless/scenes/viewer-test.cfg"
"$raytex" render "$tmp/headless/scenes/viewer-test.cfg" -o "$tmp/render.png" --width 320 --height 240 --spp 64
check screenshot-equals-render cmp -s "$tmp/shot.png" "$tmp/render.png"
check window-shows-render "$xwdDiff" "$tmp/window.xwd" "$tmp/render.png" 1

# Hot reload: saving the scene file updates the window; a parse error is printed with its
# file:line:col and the last good scene stays.
mkdir -p "$tmp/scenes"
cp "$src/scenes/textures.cfg" "$src/scenes/texture_include.cfg" "$tmp/scenes/"
ln -s "$src/textures" "$tmp/textures"
startViewer "$tmp/reload.log" reload-window-opens "$tmp/scenes/textures.cfg" -o "$tmp/scenes/shot.png" \
  --width 160 --height 120
check reload-initial waitTitle 'sphere: aSolidChecker'
sed -i -e 's|^    aSolidChecker;|    // aSolidChecker;|' -e 's|^    // aWood;|    aWood;|' "$tmp/scenes/textures.cfg"
check reload-applies waitTitle 'sphere: aWood .*reloaded'
sed -i 's|^    radius = 2.0;|    radiuss = 2.0;|' "$tmp/scenes/textures.cfg"
check reload-error-title waitTitle 'sphere: aWood .*scene error'
check reload-error-message grep -q "textures.cfg:[0-9]*:5: unknown key 'radiuss' in sphere" "$tmp/reload.log"
check reload-keeps-running kill -0 "$viewer"
sed -i 's|^    radiuss = 2.0;|    radius = 2.0;|' "$tmp/scenes/textures.cfg"
check reload-recovers waitTitle 'sphere: aWood .*reloaded'
# An image the reloaded scene names that cannot be decoded: printed, and the last good scene
# stays (every material the scene defines is loaded, so the sphere's aWood does not hide it).
sed -i "s|\"../textures/earth.jpg\"|\"$src/tests/malformed/images/truncated.png\"|" "$tmp/scenes/texture_include.cfg"
check reload-image-error-title waitTitle 'sphere: aWood .*scene error'
check reload-image-error-message grep -q "texture_include.cfg:[0-9]*:[0-9]*: cannot decode image '.*truncated.png'" \
  "$tmp/reload.log"
check reload-image-keeps-running kill -0 "$viewer"
sed -i "s|\"$src/tests/malformed/images/truncated.png\"|\"../textures/earth.jpg\"|" "$tmp/scenes/texture_include.cfg"
check reload-image-recovers waitTitle 'sphere: aWood .*reloaded'
# Reloads past the lavapipe driver's loop limit: printed, and the last good scene stays. Each
# version is good.cfg with lines added (sceneWith), written beside the scene and renamed over it,
# as sed -i does, so that a reload never reads half a file.
cp "$tmp/scenes/textures.cfg" "$tmp/scenes/good.cfg"
sceneWith() {  # sceneWith LIGHTS COUNT OBJECT: good.cfg, LIGHTS dim lights and COUNT times OBJECT
  {
    cat "$tmp/scenes/good.cfg"
    for _ in $(seq "$1"); do echo 'light { position = (-6, 10, 6); color = (0.003, 0.003, 0.003); }'; done
    for _ in $(seq "$2"); do echo "$3"; done
  } >"$tmp/scenes/next.cfg"
  mv "$tmp/scenes/next.cfg" "$tmp/scenes/textures.cfg"
}
# Known before the swap: every ray tests every plane, (255 + 1) x (252 + 3) + reserve passes.
sceneWith 254 250 'plane { normal = (0, 1, 0); distance = -3; }'
check reload-loop-limit-title waitTitle 'sphere: aWood .*scene error'
check reload-loop-limit-message grep -q "textures.cfg:[0-9]*:1: the scene has 255 lights and 252 objects every ray" \
  "$tmp/reload.log"
cp "$tmp/scenes/good.cfg" "$tmp/scenes/next.cfg"
mv "$tmp/scenes/next.cfg" "$tmp/scenes/textures.cfg"
check reload-loop-limit-recovers waitTitle 'sphere: aWood .*reloaded'
# Known only as the kernel runs: the sphere tree's walks through 1500 coincident spheres for 32
# lights (rendered headless at this size 800 of them stay within it, 1000 pass it; small, few pixels
# see them, so the failing frame is quick). The kernel's first frame of it fails, and the last
# good scene comes back (it converges, which the failed one cannot).
sceneWith 32 1500 'sphere { center = (3, 0, 0); radius = 0.1; }'
check reload-kernel-error-title waitTitle 'sphere: aWood .*scene error'
check reload-kernel-error-message grep -q "raytex: the scene needs more than 65000 loop passes" "$tmp/reload.log"
check reload-kernel-keeps-running kill -0 "$viewer"
check reload-kernel-last-good-converges waitTitle 'sphere: aWood .*| 64/64 samples .*scene error'
mv "$tmp/scenes/good.cfg" "$tmp/scenes/textures.cfg"
check reload-kernel-recovers waitTitle 'sphere: aWood .*reloaded'
# A reload that makes -o one of the scene's images: F12 then refuses to write it, says why, and
# the viewer goes on.
cp "$src/textures/uv_grid.png" "$tmp/scenes/shot.png"
sed -i 's|"../textures/earth.jpg"|"shot.png"|' "$tmp/scenes/texture_include.cfg"
sed -i -e 's|^    aWood;|    // aWood;|' -e 's|^    // anImage;|    anImage;|' "$tmp/scenes/textures.cfg"
check reload-output-image waitTitle 'sphere: anImage .*reloaded'
keyThenTitle reload-output-refused-title F12 'not saved'
check reload-output-refused-message grep -q "refusing to write '$tmp/scenes/shot.png': it is an image the scene uses" \
  "$tmp/reload.log"
check reload-output-unchanged cmp -s "$src/textures/uv_grid.png" "$tmp/scenes/shot.png"
stopViewer
check reload-clean-exit test "$rc" -eq 0 || tail -5 "$tmp/reload.log"

# The coverage filter: each sample's edge pass writes its listed pixels' sums and display
# pixels, so the window and F12 show the render's image (bit for bit in the PNG), after a key
# switched the kernels (main kernel and edge pass).
startViewer "$tmp/coverage.log" coverage-window-opens "$src/scenes/textures.cfg" -o "$tmp/coverage-shot.png" \
  --width 160 --height 120 --spp 16 --filter coverage
check coverage-accumulates waitTitle '| 16/16 samples'
keyThenTitle coverage-key-3-marble 3 'sphere: aMarble'
check coverage-converged waitTitle '| 16/16 samples'
keyThenTitle coverage-screenshot F12 "wrote $tmp/coverage-shot.png"
xwd -id "$wid" -silent >"$tmp/coverage.xwd"
stopViewer
check coverage-clean-exit test "$rc" -eq 0 || tail -5 "$tmp/coverage.log"
check coverage-no-validation-errors test "$(grep -c 'validation error' "$tmp/coverage.log")" -eq 0
sed -e 's|^    aSolidChecker;|    // aSolidChecker;|' -e 's|^    // aMarble;|    aMarble;|' "$src/scenes/textures.cfg" \
  >"$tmp/headless/scenes/coverage-test.cfg"
"$raytex" render "$tmp/headless/scenes/coverage-test.cfg" -o "$tmp/coverage-render.png" --width 160 --height 120 \
  --spp 16 --filter coverage
check coverage-screenshot-equals-render cmp -s "$tmp/coverage-shot.png" "$tmp/coverage-render.png"
check coverage-window-shows-render "$xwdDiff" "$tmp/coverage.xwd" "$tmp/coverage-render.png" 1

# The keys that teach, on the course scene at 160x120 (the sphere at pixel (80, 50), the floor at
# (80, 110), the background at (80, 2)). C prints the orbited camera: pasted into the scene it
# renders F12's image. Messages leave the title after 3 s. H, Z and U draw over the window only
# (F12's file is the render's, and the window shows the render again once they are off). Tab
# selects what the cursor is on; 1-8 and M change it; nothing selected, they change the spheres.
# windowShows PNG: the window holds PNG's pixels (within 1); windowDiffers PNG: it does not.
# Each waits up to 30 s for the window to follow a key (a loaded machine).
windowIs() { xwd -id "$wid" -silent >"$tmp/now.xwd" && "$xwdDiff" "$tmp/now.xwd" "$1" 1 >/dev/null; }
windowShows() {
  for _ in $(seq 120); do windowIs "$1" && return 0; viewerGone && return 1; sleep 0.25; done
  return 1
}
windowDiffers() {
  for _ in $(seq 120); do windowIs "$1" || return 0; viewerGone && return 1; sleep 0.25; done
  return 1
}
for filter in point box coverage; do
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/render-160-$filter.png" --width 160 --height 120 --spp 64 \
    --filter "$filter"
done
cp "$tmp/render-160-point.png" "$tmp/render-160.png"
startViewer "$tmp/keys.log" keys-window-opens "$src/scenes/textures.cfg" -o "$tmp/keys-shot.png" --width 160 \
  --height 120
check keys-converged waitTitle '| 64/64 samples'
xdotool key --window "$wid" d d w
check keys-orbit-converged waitTitle '| 64/64 samples'
keyThenTitle keys-c-message c 'camera printed to the terminal'
check keys-message-clears waitTitleGone 'camera printed'
keyThenTitle keys-help-shot-waits h '| 64/64 samples'
keyThenTitle keys-screenshot F12 "wrote $tmp/keys-shot.png"
check keys-help-on-screen windowDiffers "$tmp/keys-shot.png"
xdotool key --window "$wid" h
check keys-help-off windowShows "$tmp/keys-shot.png"
sed -n '/^camera {$/,/^}$/p' "$tmp/keys.log" >"$tmp/printed-camera.txt"
check keys-camera-block test "$(wc -l <"$tmp/printed-camera.txt")" -eq 6
# The scene with its camera block (to its closing brace) replaced by the printed one.
awk -v block="$tmp/printed-camera.txt" '/^camera / { skip = 1; while ((getline line < block) > 0) print line }
  skip { if ($0 ~ /^}/) skip = 0; next } { print }' \
  "$src/scenes/textures.cfg" >"$tmp/headless/scenes/printed-camera.cfg"
"$raytex" render "$tmp/headless/scenes/printed-camera.cfg" -o "$tmp/printed-camera.png" --width 160 --height 120 --spp 64
check keys-pasted-camera-renders-f12 cmp -s "$tmp/keys-shot.png" "$tmp/printed-camera.png"
keyThenTitle keys-reset-converged r '| 64/64 samples'
# Zoom in and out by keys and the wheel: the view changes, and comes back to the scene file's
# (the viewer keeps its camera as C would print it, so the steps cancel exactly).
for keys in "equal minus" "KP_Add KP_Subtract" "Page_Up Page_Down"; do
  xdotool key --window "$wid" "${keys% *}"
  check "keys-zoom-in-${keys% *}" windowDiffers "$tmp/render-160.png"
  xdotool key --window "$wid" "${keys#* }"
  check "keys-zoom-out-${keys#* }" windowShows "$tmp/render-160.png"
done
xdotool mousemove --window "$wid" 80 60 click --window "$wid" 4
check keys-wheel-in windowDiffers "$tmp/render-160.png"
xdotool click --window "$wid" 5
check keys-wheel-out windowShows "$tmp/render-160.png"
# V: the split screen, the render's method (point) left of the split and another right of it;
# at either edge the window is one method's render.
keyThenTitle keys-v-title v '| split: point | box'
check keys-v-converged waitTitle '| 64/64 samples'
for _ in $(seq 16); do xdotool key --window "$wid" bracketright; done
check keys-split-right-edge-is-point windowShows "$tmp/render-160.png"
for _ in $(seq 32); do xdotool key --window "$wid" bracketleft; done
check keys-split-left-edge-is-box windowShows "$tmp/render-160-box.png"
keyThenTitle keys-b-title b '| split: point | coverage'
check keys-b-converged waitTitle '| 64/64 samples'
check keys-split-coverage windowShows "$tmp/render-160-coverage.png"
xdotool mousemove --window "$wid" 40 60 mousedown --window "$wid" 3 mouseup --window "$wid" 3
check keys-split-right-button windowDiffers "$tmp/render-160.png"
check keys-split-right-button-coverage windowDiffers "$tmp/render-160-coverage.png"
keyThenTitle keys-split-screenshot F12 "wrote $tmp/keys-shot.png"
check keys-split-f12-is-the-render cmp -s "$tmp/keys-shot.png" "$tmp/render-160.png"
xdotool key --window "$wid" v
check keys-v-off waitTitleGone 'split'
check keys-v-off-shows-render windowShows "$tmp/render-160.png"
xdotool mousemove --window "$wid" 80 50
xdotool keydown --window "$wid" z
check keys-z-readout waitTitle '| sphere 1 uv (0\.[0-9]*, 0\.[0-9]*) solid ('
check keys-z-on-screen windowDiffers "$tmp/render-160.png"
xdotool keyup --window "$wid" z
check keys-z-off waitTitleGone 'uv ('
keyThenTitle keys-tab-sphere Tab '| selected: sphere 1 (textures.cfg:29): aSolidChecker |'
keyThenTitle keys-5-on-selection 5 'sphere: anImage .* selected: sphere 1 (textures.cfg:29): anImage'
xdotool keydown --window "$wid" z
check keys-z-texel waitTitle 'sphere 1 uv (.*) texel ([0-9]*, [0-9]*) of earth\.jpg'
xdotool keyup --window "$wid" z
xdotool mousemove --window "$wid" 80 110
keyThenTitle keys-tab-plane Tab '| selected: plane 1 (textures.cfg:4[0-9]): aChecker |'
keyThenTitle keys-3-on-plane 3 'sphere: anImage | plane: aMarble'
keyThenTitle keys-m-next m 'plane: aWood .* selected: plane 1 (textures.cfg:4[0-9]): aWood'
xdotool mousemove --window "$wid" 80 2
keyThenTitle keys-tab-nothing Tab 'nothing selected'
keyThenTitle keys-m-every-sphere m 'sphere: aTurbulence | plane: aWood'
keyThenTitle keys-u-title u '| uv pass'
check keys-u-converged waitTitle '| 64/64 samples'
check keys-u-on-screen windowDiffers "$tmp/render-160.png"
xdotool key --window "$wid" u
stopViewer
check keys-clean-exit test "$rc" -eq 0 || tail -5 "$tmp/keys.log"
check keys-no-validation-messages test "$(grep -c 'validation' "$tmp/keys.log")" -eq 0  # warnings neither

# The tutorial's last step (docs/tutorial.md, step 8): its scene as mine/first.cfg beside textures/;
# converged, F12 writes the image raytex render --spp 64 writes; changing marble to wood and
# saving reloads the window.
mkdir -p "$tmp/tutorial/mine"
ln -s "$src/textures" "$tmp/tutorial/textures"
bash "$src/tests/app/tutorial_steps.sh" "$src/docs/tutorial.md" "$tmp/tutorial/steps" >/dev/null
cp "$tmp/tutorial/steps/step-7.cfg" "$tmp/tutorial/mine/first.cfg"
startViewer "$tmp/tutorial.log" tutorial-window-opens "$tmp/tutorial/mine/first.cfg" -o "$tmp/tutorial/mine/shot.png" \
  --width 160 --height 120
check tutorial-materials waitTitle 'sphere: stone | plane: floor'
check tutorial-converged waitTitle '| 64/64 samples'
keyThenTitle tutorial-screenshot F12 "wrote $tmp/tutorial/mine/shot.png"
"$raytex" render "$tmp/tutorial/mine/first.cfg" -o "$tmp/tutorial/render.png" --width 160 --height 120 --spp 64
check tutorial-screenshot-equals-render cmp -s "$tmp/tutorial/mine/shot.png" "$tmp/tutorial/render.png"
xdotool mousemove --window "$wid" 80 65
keyThenTitle tutorial-tab-sphere Tab '| selected: sphere 1 (first.cfg:[0-9]*): stone |'
keyThenTitle tutorial-m-own-materials m 'sphere: floor .* selected: sphere 1 (first.cfg:[0-9]*): floor |'
sed -i 's|texture = marble { }|texture = wood { }|' "$tmp/tutorial/mine/first.cfg"
check tutorial-reload waitTitle 'sphere: stone .*reloaded'
stopViewer q
check tutorial-clean-exit test "$rc" -eq 0 || tail -5 "$tmp/tutorial.log"
check tutorial-no-validation-errors test "$(grep -c 'validation error' "$tmp/tutorial.log")" -eq 0

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
