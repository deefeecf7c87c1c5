#!/usr/bin/env bash
# The output plan and bounded input, end to end: a check can never destroy what it checks, no
# output lands beside a device, a FIFO input never hangs, scene input is bounded in bytes,
# includes and objects, and a pass name too long for its directory leaves everything as it was.
# Device nodes are made with mknod in a temporary directory (root only; skipped otherwise).
# Usage: reliability_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
small=(--width 32 --height 24)
same() { cmp -s "$1" "$2"; }
mkdir -p "$tmp/s"
cp "$src/scenes/textures.cfg" "$src/scenes/texture_include.cfg" "$tmp/s/"
cp "$src/textures/earth.jpg" "$tmp/s/"
sed -i 's|"../textures/earth.jpg"|"earth.jpg"|' "$tmp/s/texture_include.cfg"
scene=$tmp/s/textures.cfg
cd "$tmp" || exit 1
"$raytex" render "$scene" "${small[@]}" -o golden.png && cp golden.png golden.orig

# A check that would destroy what it checks: refused, nothing written (exit 2).
expect compare-self 2 "^raytex: refusing to write 'golden.png': it is the reference image --compare reads \\('golden.png'\\)$" -- \
  "$raytex" render "$scene" "${small[@]}" -o golden.png --compare golden.png --fail-rmse 0
ln -s golden.png link.png
expect compare-link 2 "refusing to write 'link.png'" -- "$raytex" render "$scene" "${small[@]}" -o link.png --compare golden.png
"$raytex" render "$scene" "${small[@]}" -o o.png --aov albedo
cp o.albedo.png albedo.orig
expect compare-own-pass 2 "refusing to write 'o.albedo.png'" -- \
  "$raytex" render "$scene" "${small[@]}" -o o.png --aov albedo --compare o.albedo.png
mkdir -p t
cp "$src/textures/uv_grid.png" t/grid.png
printf 'material g { texture = image { file = "../t/grid.png"; }; }\nsphere { radius = 1; g; }\n' >s/grid.cfg
"$raytex" render s/grid.cfg "${small[@]}" -o grid.png
expect heatmap-texture 2 "refusing to write 't/grid.png': it is an image the scene uses" -- \
  "$raytex" render s/grid.cfg "${small[@]}" -o new.png --compare grid.png --heatmap t/grid.png
ln -s s/textures.cfg scene-link.png
expect heatmap-scene-link 2 "refusing to write 'scene-link.png': it is the scene file" -- \
  "$raytex" render "$scene" "${small[@]}" -o new.png --compare golden.png --heatmap scene-link.png
expect heatmap-pass 2 "refusing to write 'o.albedo.png' twice" -- \
  "$raytex" render "$scene" "${small[@]}" -o o.png --aov albedo --compare golden.png --heatmap o.albedo.png
expect heatmap-output 2 "refusing to write 'new.png' twice: it is the image and the heat map" -- \
  "$raytex" render "$scene" "${small[@]}" -o new.png --compare golden.png --heatmap new.png
check nothing-destroyed same golden.png golden.orig
check pass-kept same o.albedo.png albedo.orig
check texture-kept same t/grid.png "$src/textures/uv_grid.png"
check scene-kept same s/textures.cfg "$src/scenes/textures.cfg"
check output-not-written test ! -e new.png

# Batches: two scenes' files, and an image one scene reads that another would write.
mkdir -p out out2 out3
cp "$scene" s/a.cfg && cp "$scene" s/a.albedo.cfg && cp "$scene" s/a.normal.cfg
expect batch-pass-and-image 2 "refusing to write 'out/a.albedo.png' twice" -- \
  "$raytex" render s/a.albedo.cfg s/a.cfg -o out/ --aov albedo "${small[@]}"
expect batch-pfm-pass 2 "refusing to write 'out2/a.normal.pfm' twice" -- \
  "$raytex" render s/a.normal.cfg s/a.cfg -o out2/ --format pfm --aov normal "${small[@]}"
cp "$src/textures/uv_grid.png" out3/t.png
printf '#include "../s/texture_include.cfg"\nmaterial u { texture = image { file = "../out3/t.png"; }; }\nsphere { radius = 1; u; }\n' >s/user.cfg
cp "$scene" s/t.cfg
expect batch-texture 2 "refusing to write 'out3/t.png': it is an image the scene 's/user.cfg' uses" -- \
  "$raytex" render s/user.cfg s/t.cfg -o out3/ "${small[@]}"
check batch-nothing-written test -z "$(ls -A out)$(ls -A out2)"
check batch-texture-kept same out3/t.png "$src/textures/uv_grid.png"

# Pass files never beside a device or FIFO.
mkfifo fifo
expect passes-beside-fifo 2 "beside 'fifo', which is not a regular file" -- "$raytex" render "$scene" "${small[@]}" -o fifo --aov normal,albedo
if mknod null c 1 3 2>/dev/null; then
  expect passes-beside-device 2 "beside 'null', which is not a regular file" -- \
    "$raytex" render "$scene" "${small[@]}" -o null --aov normal,albedo
  check passes-beside-device-nothing test -z "$(ls -d null.* 2>/dev/null)"
else
  echo "skip: cannot mknod (not root?): the device check not run"
fi

# A FIFO as an input: refused at once, never a wait (any case of .png).
mkfifo in.png IN.PNG
for f in in.png IN.PNG; do
  expect "diff-fifo-$f" 2 "^raytex: cannot open image '$f': not a regular file$" -- timeout 20 "$raytex" diff golden.png "$f"
  expect "compare-fifo-$f" 2 "not a regular file" -- timeout 20 "$raytex" render "$scene" "${small[@]}" -o c.png --compare "$f"
done
check compare-fifo-not-rendered test ! -e c.png

# Scene input is bounded: a sparse 20 GB scene and include are judged by their size.
{ cat "$scene"; } >big.cfg && truncate -s 20G big.cfg
expect sparse-scene 2 "^big.cfg:1:1: 'big.cfg' \\(21474836480 bytes\\) would bring the scene's files over 256 MiB" -- \
  timeout 20 "$raytex" render big.cfg "${small[@]}" -o big.png
printf '#include "big.cfg"\nsphere { radius = 1; }\n' >inc-big.cfg
expect sparse-include 2 "^inc-big.cfg:1:1: 'big.cfg' .* over 256 MiB" -- timeout 20 "$raytex" render inc-big.cfg "${small[@]}" -o big.png
# Under a memory limit, a large scene is out of memory (exit 1), never read in part.
if [ "${RAYTEX_SANITIZED:-0}" != 1 ]; then
  cp "$scene" mid.cfg && truncate -s 300M mid.cfg
  expect scene-out-of-memory 1 '^raytex: out of memory$' -- \
    bash -c 'ulimit -v 250000; exec "$@"' _ "$raytex" render mid.cfg --max-scene-mib 512 "${small[@]}" -o mid.png
  # 5 million spheres (45 MB): the parse stops at sphere 131073, within the memory limit.
  yes 'sphere{}' | head -n 5000000 >many.cfg
  expect sphere-limit-early 2 '^many.cfg:131073:1: sphere 131073 is over the limit: raytex renders at most 131072 spheres$' -- \
    bash -c 'ulimit -v 600000; exec "$@"' _ "$raytex" render many.cfg "${small[@]}" -o many.png
  # diff of two 2000x2000 images (4 Mpixel) within 300 MB of address space: the two images, the
  # FLIP map and rows (about 29 bytes a pixel), not copies of the images per stage.
  python3 -c '
import array, sys
w = h = 2000
for name, shift in (("wide-a.pfm", 0.0), ("wide-b.pfm", 0.1)):
    row = array.array("f", [v for x in range(w) for v in (x / w, shift + (x % 7) / 10, 0.5)]).tobytes()
    with open(name, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h) + row * h)
'
  expect diff-memory 0 '^RMSE ' -- bash -c 'ulimit -v 300000; exec "$@"' _ "$raytex" diff wide-a.pfm wide-b.pfm
fi
# Include fan-out: 10 includes a file, 16 deep, stops at the 1025th include.
for d in $(seq 0 15); do
  for _ in $(seq 10); do echo "#include \"f$((d + 1)).cfg\""; done >"f$d.cfg"
done
echo 'sphere { radius = 1; }' >f16.cfg
expect include-fan-out 2 "more than 1024 #include directives in one scene$" -- timeout 20 "$raytex" render f0.cfg "${small[@]}" -o fan.png

# A pass name over the directory's limit: refused before anything, the old image as it was.
stem=$(printf 'n%.0s' $(seq 247))
echo old >"$stem.png"
expect pass-name-too-long 2 "its name is 258 bytes, more than the 255 its directory allows" -- \
  "$raytex" render "$scene" "${small[@]}" -o "$stem.png" --aov uv,normal
check pass-name-old-image grep -qx old "$stem.png"
check pass-name-no-uv test ! -e "$stem.uv.pfm"

# diff's 16-bit PNG reader prints nothing of libpng's own: a damaged ancillary chunk is dropped
# (exit 0, no line), a truncated file is one line (exit 2).
"$raytex" render "$scene" "${small[@]}" --depth 16 -o d16.png
cp d16.png text16.png && printf 'X' | dd of=text16.png bs=1 seek=41 conv=notrunc 2>/dev/null
check png16-benign bash -c '"$0" diff d16.png text16.png >/dev/null 2>err.txt; [ $? -eq 0 ] && [ ! -s err.txt ]' "$raytex"
head -c 400 d16.png >cut16.png
check png16-truncated-one-line bash -c '"$0" diff d16.png cut16.png >/dev/null 2>err.txt; [ $? -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ]' "$raytex"

finish
