#!/usr/bin/env bash
# End-to-end checks of raytex diff: its exit codes as cmp's (0 the images pass, 1 a --fail-*
# limit exceeded, 2 any failure; docs/cli.md, "Comparing images"), its JSON, and its heat map.
# The images are the FLIP test pairs in tests/golden/flip: no Vulkan needed.
# Usage: diff_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"

pairs=$src/tests/golden/flip
a=$pairs/course_a.png
b=$pairs/course_b.png
small=$pairs/colour_a.png

# 0: equal images, and different ones when no limit is given.
expect identical 0 '^FLIP +0\.00000 \(mean\)$' -- "$raytex" diff "$a" "$a"
expect identical-psnr 0 '^PSNR +inf' -- "$raytex" diff "$a" "$a"
expect differing-no-limit 0 '^SSIM +0\.78728$' -- "$raytex" diff "$a" "$b"
expect within-limits 0 '^RMSE ' -- "$raytex" diff "$a" "$b" --fail-rmse 1 --fail-flip 1 --fail-percent 100

# 1: each limit exceeded, named on standard error (the report still on standard output).
expect fail-rmse 1 '^raytex: RMSE 0\.07[0-9]* exceeds --fail-rmse 0\.01$' -- "$raytex" diff "$a" "$b" --fail-rmse 0.01
expect fail-flip 1 '^raytex: FLIP 0\.10[0-9]* exceeds --fail-flip 0\.05$' -- "$raytex" diff "$a" "$b" --fail-flip 0.05
expect fail-percent 1 '^raytex: percent over the threshold 31\.[0-9]* exceeds --fail-percent 5$' -- \
  "$raytex" diff "$a" "$b" --fail-percent 5
expect fail-percent-threshold 0 '^over T ' -- "$raytex" diff "$a" "$b" --fail-percent 5 --threshold 0.9
"$raytex" diff "$a" "$b" --fail-rmse 0.01 --fail-flip 1 >"$tmp/report.txt" 2>"$tmp/report.err"
check fail-report-on-stdout grep -q '^FLIP ' "$tmp/report.txt"
check fail-one-line-on-stderr test "$(wc -l <"$tmp/report.err")" -eq 1

# 2: any failure.
expect missing-file 2 "^raytex: cannot open image '$tmp/none.png'" -- "$raytex" diff "$a" "$tmp/none.png"
head -c 200 "$a" >"$tmp/corrupt.png"
expect corrupt-png 2 "^raytex: cannot decode image '$tmp/corrupt.png'" -- "$raytex" diff "$tmp/corrupt.png" "$a"
expect size-mismatch 2 "^raytex: '$a' is 160x120 but '$small' is 64x48: raytex diff compares images of one size$" -- \
  "$raytex" diff "$a" "$small"
printf 'v/1\001' >"$tmp/x.exr"
expect corrupt-exr 2 "^raytex: .*$tmp/x.exr" -- "$raytex" diff "$tmp/x.exr" "$a"

# Float images (PFM, linear as stored): compared unclamped when both are of high dynamic range,
# both clamped to [0, 1] when either is an 8-bit file, refused when they hold NaN or infinity.
pfm() {  # pfm FILE WIDTH HEIGHT VALUE...: a little-endian RGB PFM
  python3 -c 'import struct, sys
w, h = int(sys.argv[2]), int(sys.argv[3])
v = [float(x) for x in sys.argv[4:]]
open(sys.argv[1], "wb").write(b"PF\n%d %d\n-1.0\n" % (w, h) + struct.pack("<%df" % len(v), *v))' "$@"
}
pfm "$tmp/two.pfm" 1 1 2 2 2
pfm "$tmp/four.pfm" 1 1 4 4 4
pfm "$tmp/nan.pfm" 1 1 1 nan 1
python3 -c 'import struct, zlib, sys
c = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + c(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0))
  + c(b"IDAT", zlib.compress(b"\0\xff\xff\xff")) + c(b"IEND", b""))' "$tmp/white.png"
expect hdr-unclamped 0 '"rmse": 2,' -- "$raytex" diff "$tmp/two.pfm" "$tmp/four.pfm" --json
expect ldr-clamps-both 0 '"rmse": 0,' -- "$raytex" diff "$tmp/white.png" "$tmp/four.pfm" --json
expect non-finite 2 "^raytex: image '$tmp/nan.pfm' holds 1 values that are not finite" -- \
  "$raytex" diff "$tmp/nan.pfm" "$tmp/two.pfm"
expect bad-option 2 '^raytex: --width is an option of raytex render, view and bench, not of diff$' -- \
  "$raytex" diff "$a" "$b" --width 5
expect bad-number 2 "^raytex: --fail-flip expects a number from 0 to 1, got 'x'$" -- "$raytex" diff "$a" "$b" --fail-flip x
expect one-image 2 '^raytex: diff needs two images' -- "$raytex" diff "$a"
expect heatmap-unwritable 2 "^raytex: cannot write '$tmp/no/dir/h.png'" -- "$raytex" diff "$a" "$b" --heatmap "$tmp/no/dir/h.png"
cp "$a" "$tmp/input.png"
ln -s "$tmp/input.png" "$tmp/link.png"
expect heatmap-over-input 2 "^raytex: refusing to write '$tmp/link.png': it is an image compared \\('$tmp/input.png'\\)$" -- \
  "$raytex" diff "$tmp/input.png" "$b" --heatmap "$tmp/link.png"
check heatmap-over-input-untouched cmp -s "$a" "$tmp/input.png"
expect heatmap-not-png 2 "^raytex: cannot write '$tmp/h.jpg': the heat map is a PNG file" -- \
  "$raytex" diff "$a" "$b" --heatmap "$tmp/h.jpg"
expect heatmap-stdout 2 '^raytex: --heatmap writes a file' -- "$raytex" diff "$a" "$b" --heatmap -
expect stdout-full 2 '^raytex: cannot write to standard output' -- bash -c '"$0" diff "$1" "$2" --json >/dev/full' \
  "$raytex" "$a" "$b"
# A device failure is 1 for render but 2 for diff: the same error kinds, diff's own mapping.
expect stdout-full-over-limit 2 '^raytex: cannot write to standard output' -- \
  bash -c '"$0" diff "$1" "$2" --fail-rmse 0 >/dev/full' "$raytex" "$a" "$b"

# --json: one object that parses, its numbers those of the table.
"$raytex" diff "$a" "$b" --json >"$tmp/report.json"
check json-exit-0 test $? -eq 0
check json-parses python3 -c 'import json,sys; json.load(sys.stdin)' <"$tmp/report.json"
check json-keys python3 -c '
import json, sys
r = json.load(sys.stdin)
want = {"a", "b", "width", "height", "rmse", "psnr", "ssim", "flip", "max_difference", "threshold",
        "percent_over_threshold"}
assert set(r) == want, set(r) ^ want
assert (r["width"], r["height"]) == (160, 120)
assert abs(r["ssim"] - 0.78728) < 1e-5 and 0.1 < r["flip"] < 0.11 and r["threshold"] == 0.01
' <"$tmp/report.json"
"$raytex" diff "$a" "$a" --json >"$tmp/equal.json"
check json-equal-psnr-null python3 -c '
import json, sys
r = json.load(sys.stdin)
assert r["psnr"] is None and r["rmse"] == 0 and r["flip"] == 0 and r["ssim"] == 1, r
' <"$tmp/equal.json"

# --json is valid UTF-8 whatever bytes the paths hold: well-formed UTF-8 is kept, each other byte
# becomes U+FFFD (a lone FF, a surrogate's encoding, an overlong '/', a sequence cut short, a
# code point past U+10FFFF). Python decodes the output strictly.
stems=(bad e smile surrogate overlong short past)
bytes=($'\xff' $'\xc3\xa9' $'\xf0\x9f\x98\x80' $'\xed\xa0\x80' $'\xc0\xaf' $'\xe2\x82' $'\xf4\x90\x80\x80')
for i in "${!stems[@]}"; do cp "$a" "$tmp/${stems[$i]}${bytes[$i]}.png"; done
for pair in "0 1" "2 3" "4 5" "6 0"; do
  read -r i j <<<"$pair"
  "$raytex" diff "$tmp/${stems[$i]}${bytes[$i]}.png" "$tmp/${stems[$j]}${bytes[$j]}.png" --json >"$tmp/bytes.json"
  check "json-utf8-${stems[$i]}-${stems[$j]}" python3 -c '
import json, sys
want = {"bad": "\ufffd", "e": "\u00e9", "smile": "\U0001f600", "surrogate": 3 * "\ufffd", "overlong": 2 * "\ufffd",
        "short": 2 * "\ufffd", "past": 4 * "\ufffd"}
r = json.loads(sys.stdin.buffer.read().decode("utf-8"))  # strict: invalid UTF-8 raises
for key, stem in (("a", sys.argv[2]), ("b", sys.argv[3])):
  assert r[key] == sys.argv[1] + "/" + stem + want[stem] + ".png", (key, r[key])
' "$tmp" "${stems[$i]}" "${stems[$j]}" <"$tmp/bytes.json"
done

# --heatmap: a PNG of the inputs' size, written atomically (no temporary file left), that raytex
# reads back.
expect heatmap 0 '^FLIP ' -- "$raytex" diff "$a" "$b" --heatmap "$tmp/heat.png"
check heatmap-png-signature test "$(od -An -tx1 -N8 "$tmp/heat.png" | tr -d ' ')" = 89504e470d0a1a0a
check heatmap-png-size test "$(od -An -tu1 -j16 -N8 "$tmp/heat.png" | tr -s ' ')" = " 0 0 0 160 0 0 0 120"
check heatmap-no-temp-file test "$(ls "$tmp" | grep -c 'heat.png.tmp')" -eq 0
expect heatmap-reads-back 0 '"width": 160, "height": 120' -- "$raytex" diff "$tmp/heat.png" "$tmp/heat.png" --json

finish
