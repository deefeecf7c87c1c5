#!/usr/bin/env bash
# Several scenes in one `raytex render` (-o DIR/): each image equals its own render's, a failing
# scene leaves the others written, the exit code is the first failure's, and bad plans are
# refused before anything renders.
# Usage: batch_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
size=(--width 48 --height 36)

for m in aMarble aWood anImage; do "$src/scripts/course-scene.sh" "$m" >"$tmp/$m.cfg"; done
mkdir -p "$tmp/out" "$tmp/one"
expect batch-three 0 '' -- "$raytex" render "$tmp/aMarble.cfg" "$tmp/aWood.cfg" "$tmp/anImage.cfg" -o "$tmp/out/" "${size[@]}"
for m in aMarble aWood anImage; do
  "$raytex" render "$tmp/$m.cfg" -o "$tmp/one/$m.png" "${size[@]}"
  check "batch-equals-single-$m" cmp -s "$tmp/out/$m.png" "$tmp/one/$m.png"
done

# A scene error in the middle: reported with its location, the others written, exit 2.
printf 'sphere {\n  radiuss = 2;\n}\n' >"$tmp/typo.cfg"
mkdir -p "$tmp/mid"
expect batch-failing-scene 2 "^$tmp/typo.cfg:2:3: " -- "$raytex" render "$tmp/aMarble.cfg" "$tmp/typo.cfg" \
  "$tmp/aWood.cfg" -o "$tmp/mid/" "${size[@]}"
expect batch-summary 2 '^raytex: 1 of 3 scenes failed$' -- "$raytex" render "$tmp/aMarble.cfg" "$tmp/typo.cfg" \
  "$tmp/aWood.cfg" -o "$tmp/mid/" "${size[@]}"
check batch-others-written test -s "$tmp/mid/aMarble.png" -a -s "$tmp/mid/aWood.png" -a ! -e "$tmp/mid/typo.png"

# The exit code is the first failure's: an output that cannot be written (1: a file size limit
# of 1 KiB, under the 160x120 image) before a scene error (2), and the other way round.
mkdir -p "$tmp/first"
expect batch-first-io 1 "cannot write '$tmp/first/aMarble.png': File too large" -- bash -c 'ulimit -f 1; exec "$@"' _ \
  "$raytex" render "$tmp/aMarble.cfg" "$tmp/typo.cfg" -o "$tmp/first/" --width 160 --height 120
expect batch-first-scene 2 '^raytex: 2 of 2 scenes failed$' -- bash -c 'ulimit -f 1; exec "$@"' _ \
  "$raytex" render "$tmp/typo.cfg" "$tmp/aMarble.cfg" -o "$tmp/first/" --width 160 --height 120
# A directory in the place of an image: the whole batch is refused before anything renders.
mkdir -p "$tmp/dir-in-the-way/aMarble.png"
expect batch-directory-in-the-way 1 "^raytex: cannot write '$tmp/dir-in-the-way/aMarble.png': Is a directory$" -- \
  "$raytex" render "$tmp/aWood.cfg" "$tmp/aMarble.cfg" -o "$tmp/dir-in-the-way/" "${size[@]}"
check batch-directory-in-the-way-nothing test ! -e "$tmp/dir-in-the-way/aWood.png"

# Refused before anything renders (exit 2, nothing written).
expect batch-needs-directory 2 'give -o DIR/' -- "$raytex" render "$tmp/aMarble.cfg" "$tmp/aWood.cfg" -o "$tmp/x.png"
check batch-needs-directory-nothing test ! -e "$tmp/x.png"
expect batch-missing-directory 2 "^raytex: -o $tmp/none/: no such directory" -- "$raytex" render \
  "$tmp/aMarble.cfg" "$tmp/aWood.cfg" -o "$tmp/none/"
check batch-missing-directory-nothing test ! -e "$tmp/none"
touch "$tmp/file"
expect batch-not-a-directory 2 "not a directory" -- "$raytex" render "$tmp/aMarble.cfg" -o "$tmp/file/"
mkdir -p "$tmp/b" "$tmp/same"
cp "$tmp/aMarble.cfg" "$tmp/b/aMarble.cfg"
expect batch-same-output 2 "refusing to write '$tmp/same/aMarble.png' twice: it is the image of '$tmp/aMarble.cfg' and the image of '$tmp/b/aMarble.cfg'" -- "$raytex" render "$tmp/aMarble.cfg" \
  "$tmp/b/aMarble.cfg" -o "$tmp/same/"
expect batch-same-scene-twice 2 "refusing to write '$tmp/same/aMarble.png' twice" -- "$raytex" render "$tmp/aMarble.cfg" "$tmp/aMarble.cfg" \
  -o "$tmp/same/"
check batch-same-nothing test -z "$(ls "$tmp/same")"
expect batch-format-needs-directory 2 '^raytex: --format applies to -o DIR/' -- "$raytex" render \
  "$tmp/aMarble.cfg" -o "$tmp/x.png" --format png
expect batch-stats 2 '^raytex: --stats times one render' -- "$raytex" render "$tmp/aMarble.cfg" -o "$tmp/same/" --stats
expect batch-view 2 'more than one scene given' -- "$raytex" view "$tmp/aMarble.cfg" "$tmp/aWood.cfg"
expect batch-bench-directory 2 '^raytex: -o DIR/ is for raytex render' -- "$raytex" bench "$tmp/aMarble.cfg" -o "$tmp/same/"
if [ "$(id -u)" -ne 0 ]; then
  mkdir -p "$tmp/ro" && chmod a-w "$tmp/ro"
  expect batch-unwritable-directory 1 "cannot write into '$tmp/ro/'" -- "$raytex" render "$tmp/aMarble.cfg" -o "$tmp/ro/"
fi

finish
