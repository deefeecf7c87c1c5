#!/usr/bin/env bash
# End-to-end checks of the raytex command line: exit codes (0 ok, 1 runtime, 2 bad
# input; docs/cli.md), one-line errors, file:line:col for scenes, atomic output.
# Usage: cli_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"

expect help 0 '^  raytex render SCENE\.\.\. \[-o FILE\]' -- "$raytex" --help
expect help-kinds 0 'texture kinds: image, checker, solid_checker, [a-z_, ]+ or [a-z_]+$' -- "$raytex" --help
expect no-args 2 '^raytex: missing command' -- "$raytex"
expect unknown-command 2 "unknown command 'draw'" -- "$raytex" draw x
expect no-scene 2 'render needs a scene file' -- "$raytex" render
expect bad-width 2 '--width expects an integer from 1 to 16384' -- "$raytex" render s.cfg --width 0
expect bad-option 2 "unknown option '--fast' \\(try raytex --help\\)$" -- "$raytex" render s.cfg --fast
expect near-option 2 "^raytex: unknown option '--fliter' \\(did you mean '--filter'\\?\\)$" -- "$raytex" render s.cfg --fliter box
expect missing-scene 2 "^$tmp/none.cfg: cannot open" -- "$raytex" render "$tmp/none.cfg"

# The scenes and images of the course, copied: the variants below are written beside them.
mkdir -p "$tmp/course"
cp -r "$src/scenes" "$src/textures" "$tmp/course/"
course=$tmp/course/scenes

# A sphere left in the default material while the scene defines textured ones: one note on
# stderr at the sphere, naming how to give it one; the render goes on (exit 0, image written).
# A scene whose objects all name a material gets none.
sed 's|^    aSolidChecker;|    // aSolidChecker;|' "$course/textures.cfg" >"$course/plain.cfg"
"$raytex" render "$course/plain.cfg" -o "$tmp/plain.png" --width 16 --height 12 2>"$tmp/plain.err"
check default-material-exit-0 test $? -eq 0
check default-material-output test -s "$tmp/plain.png"
check default-material-one-note test "$(wc -l <"$tmp/plain.err")" -eq 1
check default-material-note grep -qE "^$course/plain.cfg:29:1: note: this sphere names no material, so it is plain \
grey \(the default material\); the scene defines textured materials \(aChecker, aSolidChecker, aNoise, aMarble, \
\.\.\.\): to use one, name it inside the object's block, e\.g\. 'aChecker;'\$" "$tmp/plain.err"
"$raytex" render "$course/textures.cfg" -o "$tmp/textured.png" --width 16 --height 12 2>"$tmp/textured.err"
check textured-no-note test ! -s "$tmp/textured.err"

printf 'sphere {\n  center = (0, 0, 0);\n  radiuss = 2;\n}\n' >"$tmp/typo.cfg"
expect scene-error 2 "^$tmp/typo.cfg:3:3: " -- "$raytex" render "$tmp/typo.cfg" -o "$tmp/typo.png"
check scene-error-no-output test ! -e "$tmp/typo.png"

# Messages never grow with the input nor quote a file that is not a scene (docs/security.md).
{ printf 'sphere { '; head -c 10485760 /dev/zero | tr '\0' a; printf ' = 1; }\n'; } >"$tmp/huge-ident.cfg"
"$raytex" render "$tmp/huge-ident.cfg" -o "$tmp/huge-ident.png" 2>"$tmp/huge-ident.err"
check huge-identifier-exit-2 test $? -eq 2
check huge-identifier-short-message test "$(wc -c <"$tmp/huge-ident.err")" -lt 300
printf 'hunter2isMyPassword\n' >"$tmp/token.txt"
printf '#include "token.txt"\nsphere { }\n' >"$tmp/inc-token.cfg"
expect include-not-a-scene 2 "^$tmp/inc-token.cfg:1:1: '$tmp/token.txt' is not a scene file\$" -- \
  "$raytex" render "$tmp/inc-token.cfg" -o "$tmp/x.png"
expect scene-not-a-scene 2 "^$tmp/token.txt:1:1: '$tmp/token.txt' is not a scene file\$" -- \
  "$raytex" render "$tmp/token.txt" -o "$tmp/x.png"

# --allow-read: includes and images only inside the given trees (the scene itself always).
mkdir -p "$tmp/jail" "$tmp/outside"
printf 'material m { }\n' >"$tmp/outside/mats.cfg"
printf 'camera { eye = (0, 0, 5); lookat = (0, 0, 0); }\n#include "../outside/mats.cfg"\nsphere { m; }\n' \
  >"$tmp/jail/s.cfg"
expect allow-read-refuses 2 "^$tmp/jail/s.cfg:2:10: '$tmp/jail/../outside/mats.cfg' is outside the directories --allow-read allows\$" -- \
  "$raytex" render "$tmp/jail/s.cfg" -o "$tmp/jail.png" --allow-read "$tmp/jail"
check allow-read-no-output test ! -e "$tmp/jail.png"
expect allow-read-two-dirs 0 '' -- "$raytex" render "$tmp/jail/s.cfg" -o "$tmp/jail.png" --width 8 --height 8 \
  --allow-read "$tmp/jail" --allow-read "$tmp/outside"
expect allow-read-relative 0 '' -- bash -c "cd '$tmp' && '$raytex' render jail/s.cfg -o jail.png --width 8 \
  --height 8 --allow-read outside --allow-read ./jail/"
expect allow-read-reference 2 'is outside the directories --allow-read allows' -- "$raytex" render \
  "$tmp/jail/s.cfg" -o "$tmp/jail.png" --reference --allow-read "$tmp/jail"
expect allow-read-bench 2 'is outside the directories --allow-read allows' -- "$raytex" bench \
  "$tmp/jail/s.cfg" --allow-read "$tmp/jail"

expect no-driver 1 'mesa-vulkan-drivers' -- env VK_ICD_FILENAMES=/nonexistent.json "$raytex" render \
  "$src/scenes/textures.cfg" -o "$tmp/none.png"
check no-driver-no-output test ! -e "$tmp/none.png"

expect unwritable 1 "cannot write '$tmp/no/dir/x.png'" -- "$raytex" render "$src/scenes/textures.cfg" \
  -o "$tmp/no/dir/x.png" --width 32 --height 24

# A full disk: a file size limit of 1 KiB makes the write fail as a full file system would (EFBIG
# here, ENOSPC there; SIGXFSZ ignored so that write returns the error). One line, exit 1, and
# neither the PNG nor its temporary file is left.
expect full-disk 1 "^raytex: cannot write '$tmp/full.png': File too large$" -- bash -c \
  'trap "" XFSZ; ulimit -f 1; exec "$0" render "$1" -o "$2" --width 320 --height 240' \
  "$raytex" "$src/scenes/textures.cfg" "$tmp/full.png"
check full-disk-no-output test ! -e "$tmp/full.png"
check full-disk-no-temp-file test "$(ls "$tmp" | grep -c 'full.png.tmp')" -eq 0

# Large renders: over the command line's limit, refused before any work; over the device's
# storage-buffer range (lavapipe: 128 MiB, 2048 rows of 4096 vec4s), rendered in bands of rows.
expect huge-16384 2 '^raytex: 16384x16384 exceeds the limit of 67108864 pixels \(8192x8192\)$' -- \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/huge.png" --width 16384 --height 16384
check huge-no-output test ! -e "$tmp/huge.png"
expect banded 0 '\| 4096x4096, 1 spp$' -- env VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/banded.png" --width 4096 --height 4096 --stats
check banded-png-size test "$(od -An -tu1 -j16 -N8 "$tmp/banded.png" | tr -s ' ')" = " 0 0 16 0 0 0 16 0"
# Out of memory: with 500 MB of address space lavapipe starts, but cannot allocate a 4K image's
# 127 MiB output buffer. (With less than about 250 MB, lavapipe's own vkCreateDevice crashes.)
# (Not under ASan, tests/sanitize/run.sh: its shadow memory needs terabytes of address space.)
# Without the validation layer: its worker threads' stacks, in so little address space, fail to
# start at some limits, which the layer reports as an exception through the Vulkan call.
if [ "${RAYTEX_SANITIZED:-0}" != 1 ]; then
  expect out-of-memory 1 '^raytex: out of memory: the Vulkan device could not allocate 127 MiB' -- \
    env RAYTEX_VALIDATION=0 LP_NUM_THREADS=2 bash -c 'ulimit -v 500000; exec "$0" render "$1" -o "$2" --width 3840 --height 2160' \
    "$raytex" "$src/scenes/textures.cfg" "$tmp/oom.png"
  check out-of-memory-no-output test ! -e "$tmp/oom.png"
fi

# Validation layers, synchronization validation included, find nothing in a headless render.
expect validate-clean 0 '' -- "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/valid.png" --width 64 \
  --height 48 --spp 4 --validate
check validate-no-errors bash -c "! '$raytex' render '$src/scenes/textures.cfg' -o '$tmp/valid.png' --width 64 \
  --height 48 --spp 4 --validate 2>&1 | grep -q 'validation'"

# Success: a PNG of the requested size, and the stats line.
expect render 0 '^device [0-9.]+ ms \| parse [0-9.]+ ms .* encode [0-9.]+ ms \| images 0.0 MiB \| 64x48, 1 spp$' -- \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/ok.png" --width 64 --height 48 --stats
# The image textures' GPU memory: the sum of their own chains (earth.jpg 2048x1024: 8.0 MiB,
# 10.7 MiB with the box filter's mip levels).
sed 's|^    aSolidChecker;|    anImage;|' "$course/textures.cfg" >"$course/image.cfg"
expect stats-images 0 '\| images 8.0 MiB \| 64x48, 1 spp$' -- \
  "$raytex" render "$course/image.cfg" -o "$tmp/ok.png" --width 64 --height 48 --stats
expect stats-images-box 0 '\| images 10.7 MiB \| 64x48, 1 spp$' -- \
  "$raytex" render "$course/image.cfg" -o "$tmp/ok.png" --width 64 --height 48 --stats --filter box
# The coverage filter's edge pixels: the sphere's silhouette, its shadow and the horizon cross
# some of the 3072.
expect stats-edge-pixels 0 '\| 64x48, 1 spp \| [1-9][0-9]+ edge pixels$' -- \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/ok.png" --width 64 --height 48 --stats --filter coverage
# With 4 spp each sample's edge pass shades the samples whose cells an edge crosses.
expect stats-edge-samples 0 '\| 64x48, 4 spp \| [1-9][0-9]+ edge samples$' -- \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/ok.png" --width 64 --height 48 --stats --filter coverage --spp 4
# Passes with the coverage filter: the box kernel's, from the pixel centre.
expect coverage-passes 0 '' -- \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/passes.exr" --width 64 --height 48 --filter coverage --aov footprint,uv
check coverage-passes-file test -s "$tmp/passes.exr"
# Image filter methods: with the box filter, named in the PNG's metadata; with point, exit 2.
expect image-filter-ewa 0 '' -- \
  "$raytex" render "$course/image.cfg" -o "$tmp/ewa.png" --width 64 --height 48 --filter box --image-filter ewa
check image-filter-metadata grep -aq 'Image filter.ewa' "$tmp/ewa.png"
expect image-filter-point 2 '^raytex: image filter ewa filters over the footprint: add --filter box or coverage' -- \
  "$raytex" render "$course/image.cfg" -o "$tmp/ewa.png" --width 64 --height 48 --image-filter ewa
check png-signature test "$(head -c 8 "$tmp/ok.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a
check png-size test "$(od -An -tu1 -j16 -N8 "$tmp/ok.png" | tr -s ' ')" = " 0 0 0 64 0 0 0 48"
check no-temp-files test "$(ls "$tmp" | grep -c tmp-)" -eq 0

expect help-view-keys 0 'F12 .*write -o FILE' -- "$raytex" --help
expect view-reference 2 '^raytex: --reference is an option of raytex render, not of view$' -- "$raytex" view s.cfg --reference
expect view-frames 2 '--frames expects an integer from 1' -- "$raytex" view s.cfg --frames 0
expect render-frames 2 '^raytex: --frames is an option of raytex view, not of render$' -- "$raytex" render s.cfg --frames 5
# No display: the viewer says to render to a file instead, exit 1.
expect view-no-display 1 'no display.*raytex render' -- env -u DISPLAY -u WAYLAND_DISPLAY "$raytex" view \
  "$src/scenes/textures.cfg"

# The option table (docs/cli.md): --name=value, options without effect refused, the output's
# name checked before any work, - for standard output.
expect equals-form 0 '\| 32x24, 1 spp$' -- "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/eq.png" --width=32 \
  --height=24 --stats
expect flag-with-value 2 '^raytex: --stats takes no value$' -- "$raytex" render s.cfg --stats=1
for option in "--filter box" "--device 0" "--validate"; do
  # shellcheck disable=SC2086  # the option's words
  expect "no-effect-reference-${option%% *}" 2 "^raytex: ${option%% *} has no effect with --reference: " -- \
    "$raytex" render "$src/scenes/textures.cfg" --reference $option -o "$tmp/no-effect.png"
done
check no-effect-no-output test ! -e "$tmp/no-effect.png"
expect bench-stats 2 '^raytex: --stats is an option of raytex render and view, not of bench$' -- \
  "$raytex" bench "$src/scenes/textures.cfg" --stats
expect output-extension 2 "^raytex: '$tmp/out.jpg': unknown output format \(supported: .png, .exr, .pfm\)$" -- \
  "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/out.jpg" --width 8 --height 6
check output-extension-nothing-written test ! -e "$tmp/out.jpg"
expect output-extension-case 0 '' -- "$raytex" render "$src/scenes/textures.cfg" -o "$tmp/upper.PNG" --width 8 --height 6
"$raytex" render "$src/scenes/textures.cfg" -o - --width 32 --height 24 >"$tmp/stdout.png"
check stdout-exit-0 test $? -eq 0
check stdout-same-png cmp -s "$tmp/stdout.png" "$tmp/eq.png"
"$raytex" render "$src/scenes/textures.cfg" -o - --width 32 --height 24 --reference >"$tmp/stdout-reference.png"
check stdout-reference-png test "$(head -c 8 "$tmp/stdout-reference.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a
expect stdout-with-stats 2 '^raytex: --stats prints to standard output, which -o - fills with the PNG$' -- \
  "$raytex" render "$src/scenes/textures.cfg" -o - --stats
expect stdout-bench 2 '^raytex: -o - \(standard output\) is for raytex render' -- "$raytex" bench "$src/scenes/textures.cfg" -o -

if command -v script >/dev/null; then  # a terminal on standard output (util-linux's script)
  expect stdout-terminal 2 'which is a terminal' -- script -qec \
    "'$raytex' render '$src/scenes/textures.cfg' -o - --width 8 --height 6" /dev/null
fi

# The scene's render block sets size, samples and filter; flags override it.
sed 's|^camera {|render { width = 40; height = 30; spp = 4; filter = box; }\ncamera {|' \
  "$course/textures.cfg" >"$course/render.cfg"
expect render-block 0 '\| 40x30, 4 spp$' -- "$raytex" render "$course/render.cfg" -o "$tmp/rb.png" --stats
expect render-block-override 0 '\| 20x30, 1 spp$' -- "$raytex" render "$course/render.cfg" \
  -o "$tmp/rb.png" --stats --width 20 --spp 1
sed 's|^camera {|render { width = 9000; height = 9000; }\ncamera {|' \
  "$course/textures.cfg" >"$course/big.cfg"
expect render-block-too-big 2 '9000x9000 exceeds the limit' -- "$raytex" render "$course/big.cfg" -o "$tmp/big.png"

# bench: usage errors, the table, JSON that parses with every phase, and no file unless -o.
expect bench-runs 2 '--runs expects an integer from 1 to 1000' -- "$raytex" bench s.cfg --runs 0
expect bench-no-scene 2 'bench needs a scene file' -- "$raytex" bench --json
expect render-json 2 '^raytex: --json is an option of raytex bench and diff, not of render$' -- "$raytex" render s.cfg --json
expect bench-scene-error 2 "^$tmp/typo.cfg:3:3: " -- "$raytex" bench "$tmp/typo.cfg"
expect bench-table 0 'frame \(GPU timestamps\) +[0-9.]+' -- "$raytex" bench "$src/scenes/textures.cfg" \
  --width 32 --height 24 --runs 2
(cd "$tmp" && "$raytex" bench "$src/scenes/textures.cfg" --width 32 --height 24 --spp 4 --runs 1 --json \
  >"$tmp/bench.json")
check bench-json cmake -D JSON_FILE="$tmp/bench.json" -D WIDTH=32 -D HEIGHT=24 -D SPP=4 \
  -P "$src/tests/app/bench_json_check.cmake"
check bench-no-output test ! -e "$tmp/out.png"
expect bench-output 0 'end to end' -- "$raytex" bench "$src/scenes/textures.cfg" --width 32 --height 24 --runs 1 \
  -o "$tmp/bench.png"
check bench-output-png test "$(od -An -tu1 -j16 -N8 "$tmp/bench.png" | tr -s ' ')" = " 0 0 0 32 0 0 0 24"

# An existing output is replaced whole, never left half-written, on success and failure.
cp "$tmp/ok.png" "$tmp/keep.png"
expect keep-on-error 2 'typo.cfg:3:3' -- "$raytex" render "$tmp/typo.cfg" -o "$tmp/keep.png"
check keep-on-error-unchanged cmp -s "$tmp/ok.png" "$tmp/keep.png"

# Determinism: the same scene rendered twice, in two processes, gives the same PNG bytes (a
# noise material, an image texture and 4 spp: the paths most likely to vary).
for i in 1 2; do
  "$raytex" render "$src/scenes/textures.cfg" --width 96 --height 72 --spp 4 -o "$tmp/same-$i.png" >/dev/null 2>&1
  sed -e 's|^    aSolidChecker;|    // aSolidChecker;|' -e 's|^    // aMarble;|    aMarble;|' \
    -e 's|^    aChecker;|    anImage;|' "$course/textures.cfg" >"$course/determinism.cfg"
  "$raytex" render "$course/determinism.cfg" --width 96 --height 72 --spp 4 -o "$tmp/marble-$i.png" \
    >/dev/null 2>&1
done
check deterministic-default cmp -s "$tmp/same-1.png" "$tmp/same-2.png"
check deterministic-marble-image cmp -s "$tmp/marble-1.png" "$tmp/marble-2.png"
check deterministic-differs bash -c "! cmp -s '$tmp/same-1.png' '$tmp/marble-1.png'"

# Lavapipe ends a kernel's loops after 65535 passes. A scene whose rays test every object (264:
# 256 planes, 255 of them below the floor, and 8 spheres, too few for a sphere tree) with 62
# lights (61 dark) at 4 spp would pass it in one dispatch, so the samples go one per dispatch.
# The image equals the one with the lit light alone (there, all 4 samples in one dispatch).
manyLights() {  # manyLights DARK_LIGHTS
  echo 'camera { eye = (0, 3, 12); lookat = (0, -0.5, 0); }'
  for _ in $(seq "$1"); do echo 'light { position = (0, 10, 6); color = (0, 0, 0); }'; done
  echo 'light { position = (-6, 10, 6); color = (1, 1, 1); }'
  for _ in $(seq 7); do echo 'sphere { center = (0, 0, 40); radius = 1; }'; done
  echo 'sphere { center = (0, 0, 0); radius = 2; }'
  for _ in $(seq 255); do echo 'plane { normal = (0, 1, 0); distance = -50; }'; done
  echo 'plane { normal = (0, 1, 0); distance = -2; }'
}
manyLights 61 >"$tmp/lights62.cfg"
manyLights 0 >"$tmp/lights1.cfg"
for n in 62 1; do
  "$raytex" render "$tmp/lights$n.cfg" --width 32 --height 24 --spp 4 -o "$tmp/lights$n.png" >/dev/null 2>&1
done
check loop-limit-per-sample cmp -s "$tmp/lights62.png" "$tmp/lights1.png"
# Over the limit in one sample (245 lights, 264 objects): refused on lavapipe after device
# selection, at the first light over (the 243rd); the CPU reference has no such limit.
manyLights 244 >"$tmp/lights245.cfg"
expect loop-limit-lavapipe 2 "^$tmp/lights245.cfg:244:1: the scene has 245 lights and 264 objects every ray tests: .* the lavapipe driver runs\$" \
  -- "$raytex" render "$tmp/lights245.cfg" --width 8 --height 6 -o "$tmp/lights245.png"
expect loop-limit-reference 0 '' -- "$raytex" render "$tmp/lights245.cfg" --reference --width 8 --height 6 \
  -o "$tmp/lights245-reference.png"
# A sphere tree's walks are counted while the kernel runs (shaders/loop_budget.glsl). One pixel
# looks along a row of N small spheres to a wall, the light behind the camera: the ray misses
# every sphere but enters every box of the tree (the spheres alternate above and below it), and
# so does the shadow ray back from the wall. With 100000 spheres the two walks pass the limit
# (exit 1, nothing written); with 2000, one light passes far below it, and 256 lights pass it.
sphereRow() {  # sphereRow SPHERES LIGHTS
  echo 'camera { eye = (-1, 0, 0); lookat = (1, 0, 0); up = (0, 1, 0); fov = 10; }'
  echo 'ambient_light = (0, 0, 0);'
  for _ in $(seq "$2"); do echo 'light { position = (-2, 0, 0); color = (0.004, 0.004, 0.004); }'; done
  awk -v n="$1" 'BEGIN { for (i = 0; i < n; ++i) printf "sphere { center = (%g, %g, 0); radius = 0.1; }\n", 0.3 * i, i % 2 ? 0.2 : -0.2 }'
  echo "plane { normal = (-1, 0, 0); distance = $(awk -v n="$1" 'BEGIN { print -(0.3 * n + 1) }'); }"
}
budget='^raytex: the scene needs more than 65000 loop passes .* for one group of 8 pixels, more than the lavapipe driver runs: .*$'
sphereRow 100000 1 >"$tmp/row100000.cfg"
expect loop-budget-one-light 1 "$budget" -- "$raytex" render "$tmp/row100000.cfg" --width 1 --height 1 -o "$tmp/row100000.png"
check loop-budget-nothing-written test ! -e "$tmp/row100000.png"
sphereRow 2000 256 >"$tmp/row2000-256.cfg"
expect loop-budget-256-lights 1 "$budget" -- "$raytex" render "$tmp/row2000-256.cfg" --width 1 --height 1 -o "$tmp/row.png"
sphereRow 2000 1 >"$tmp/row2000-1.cfg"
expect loop-budget-within 0 '' -- "$raytex" render "$tmp/row2000-1.cfg" --width 1 --height 1 -o "$tmp/row2000-1.png"
"$raytex" render "$tmp/row2000-1.cfg" --reference --width 1 --height 1 -o "$tmp/row2000-1-reference.png" >/dev/null 2>&1
check loop-budget-within-matches-reference cmp -s "$tmp/row2000-1.png" "$tmp/row2000-1-reference.png"
# Object counts are the scene model's: the same error from the GPU path and the reference.
awk 'BEGIN { for (i = 0; i <= 131072; ++i) print "sphere { radius = 1; }" }' >"$tmp/spheres131073.cfg"
for command in render "render --reference"; do
  # shellcheck disable=SC2086  # the command's words
  expect "sphere-limit-${command// /-}" 2 "^$tmp/spheres131073.cfg:131073:1: sphere 131073 is over the limit: raytex renders at most 131072 spheres\$" \
    -- "$raytex" $command "$tmp/spheres131073.cfg" --width 8 --height 6 -o "$tmp/spheres131073.png"
done

# Image files are checked from their headers before anything is decoded: a budget of 1 MiB
# refuses earth.jpg (2048x1024, 8 MiB) on every command that loads images, at its `file` value.
printf 'material e { texture = image { file = "%s/textures/earth.jpg"; }; }\nsphere { radius = 1; e; }\n' \
  "$src" >"$tmp/earth.cfg"
for command in render "render --reference" bench; do
  # shellcheck disable=SC2086  # the command's words
  expect "image-budget-${command// /-}" 2 "^$tmp/earth.cfg:1:39: image '$src/textures/earth.jpg' \(2048x1024\) brings \
the scene's images to 8.0 MiB on the GPU \(1 image at its own size, 4 bytes a texel\), over the budget of 1 MiB \
\(--max-image-mib N raises it\)$" -- "$raytex" $command "$tmp/earth.cfg" --max-image-mib 1 -o "$tmp/budget.png"
done
check image-budget-no-output test ! -e "$tmp/budget.png"
# An image path that is a FIFO is refused at once (opening it would wait for a writer).
if mkfifo "$tmp/pipe.png"; then
  printf 'material e { texture = image { file = "pipe.png"; }; }\nsphere { radius = 1; e; }\n' >"$tmp/fifo.cfg"
  expect image-fifo 2 "^$tmp/fifo.cfg:1:39: cannot open image '$tmp/pipe.png': not a regular file$" -- \
    timeout 10 "$raytex" render "$tmp/fifo.cfg" -o "$tmp/fifo.png"
else
  echo "skip image-fifo: mkfifo failed"
fi

# Loading holds at most 1.5 times an image's decoded bytes: the 4096x4096 render above as a
# texture (64 MiB decoded, 85.3 MiB with mip levels) loads within 96 MiB more than the program's
# 32 MiB of address space. With no Vulkan driver only parsing and loading run, so the run ends
# with the no-driver error, not out of memory. (Not under ASan: see out-of-memory above.)
if [ "${RAYTEX_SANITIZED:-0}" != 1 ] && [ -e "$tmp/banded.png" ]; then
  printf 'material e { texture = image { file = "banded.png"; }; }\nsphere { radius = 1; e; }\n' >"$tmp/big.cfg"
  for filter in point box; do
    expect "image-load-memory-$filter" 1 '^raytex: no Vulkan device found' -- env VK_ICD_FILENAMES=/nonexistent.json \
      bash -c 'ulimit -v $((32768 + 98304)); exec "$0" render "$1" -o "$2" --filter "$3"' \
      "$raytex" "$tmp/big.cfg" "$tmp/big.png" "$filter"
  done
fi

# Values at the ends of the float range render finite: exit 0 and no "non-finite colour values"
# warning (the render fuzz test's reproducers, tests/fuzz/render_seeds/).
for seed in plane-tex-scale-1e-38 checker-squares-3e38 colours-3e38; do
  check "finite-$seed" bash -c "out=\$('$raytex' render '$src/tests/fuzz/render_seeds/$seed.cfg' \
    -o '$tmp/$seed.png' --width 32 --height 24 2>&1) && [ -z \"\$out\" ]"
done

finish
