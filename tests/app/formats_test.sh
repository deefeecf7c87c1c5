#!/usr/bin/env bash
# Output formats end to end: -o by extension (PNG 8/16 bits, EXR float/half, half's range
# clamped, PFM), metadata, passes (--aov) as EXR layers or files beside the image, -o DIR/
# --format, and render --compare with its exit codes. Round trips go through raytex diff
# against the PNG.
# Usage: formats_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
scene=$src/scenes/textures.cfg
size=(--width 64 --height 48)
render() { "$raytex" render "$scene" "${size[@]}" "$@"; }

# The same view in every format. The PNG's 8-bit sRGB codes lie within half a step of the float
# values: at most (1 - srgb^-1(254/255)) / 2 = 0.00445 in linear, the widest half step.
render -o "$tmp/a.png" && render -o "$tmp/a.exr" && render -o "$tmp/a.pfm" && render -o "$tmp/h.exr" --half
expect exr-within-8-bit 0 'over T +0.000%' -- "$raytex" diff "$tmp/a.exr" "$tmp/a.png" --threshold 0.00445 --fail-percent 0
expect pfm-within-8-bit 0 'over T +0.000%' -- "$raytex" diff "$tmp/a.pfm" "$tmp/a.png" --threshold 0.00445 --fail-percent 0
expect pfm-equals-exr 0 'RMSE +0 ' -- "$raytex" diff "$tmp/a.pfm" "$tmp/a.exr" --fail-rmse 0
# Half floats: 11 significant bits, a relative error of at most 2^-11.
expect half-near-float 0 '' -- "$raytex" diff "$tmp/h.exr" "$tmp/a.exr" --fail-rmse 0.0005
check exr-magic test "$(head -c 4 "$tmp/a.exr" | od -An -tx1 | tr -d ' \n')" = 762f3101
check pfm-header test "$(head -c 13 "$tmp/a.pfm")" = "$(printf 'PF\n64 48\n-1.0')"
check half-smaller test "$(stat -c %s "$tmp/h.exr")" -lt "$(stat -c %s "$tmp/a.exr")"
check half-in-range-silent test -z "$(render -o "$tmp/h2.exr" --half 2>&1)"

# Half floats end at 65504: a finite value beyond is written as +-65504 (not an infinity, which
# raytex diff refuses), with one warning line. Every pixel of this view is the background, whose
# R of 1e5 is beyond the range and whose G and B are halves exactly: 64 x 48 values clamped, each
# 1e5 - 65504 = 34496 under the float render's, an RMSE over the 3 channels of 34496 / sqrt(3).
cat >"$tmp/bright.cfg" <<'EOF'
camera { eye = (0, 0, 5); lookat = (0, 0, 0); up = (0, 1, 0); fov = 40; }
light { position = (3, 4, 5); color = (1, 1, 1); }
background = (100000, 0.25, 2);
sphere { center = (0, 0, 20); radius = 1; }  // behind the eye
EOF
clamped='warning: 3072 values over the half-float range clamped to +-65504'
bright() { "$raytex" render "$tmp/bright.cfg" "${size[@]}" "$@" 2>&1; }
out=$(bright -o "$tmp/bh.exr" --half)
check half-clamp-exit-0 test $? -eq 0
check half-clamp-one-warning test "$out" = "$clamped"
expect half-clamp-finite 0 'RMSE +0 ' -- "$raytex" diff "$tmp/bh.exr" "$tmp/bh.exr" --fail-rmse 0
bright -o "$tmp/bf.exr" >/dev/null
expect half-clamp-rmse 0 'RMSE +19916\.3 ' -- "$raytex" diff "$tmp/bf.exr" "$tmp/bh.exr"
expect half-clamp-to-65504 0 'max diff +34496 ' -- "$raytex" diff "$tmp/bf.exr" "$tmp/bh.exr"
check half-clamp-reference test "$(bright -o "$tmp/br.exr" --half --reference)" = "$clamped"
mkdir -p "$tmp/bd"
check half-clamp-batch test "$(bright -o "$tmp/bd/" --format exr --half)" = "$clamped"
check half-clamp-batch-finite "$raytex" diff "$tmp/bd/bright.exr" "$tmp/bh.exr" --fail-rmse 0

render -o "$tmp/d.png" --depth 16
check png-16-bit test "$(od -An -tu1 -j24 -N1 "$tmp/d.png" | tr -d ' ')" = 16
# Read back at 16 bits: closer to the float image than the 8-bit PNG, within half a 16-bit step.
expect png-16-near-float 0 'over T +0.000%' -- "$raytex" diff "$tmp/d.png" "$tmp/a.exr" --threshold 0.00002 --fail-percent 0
expect png-8-not-that-near 1 '' -- "$raytex" diff "$tmp/a.png" "$tmp/a.exr" --threshold 0.00002 --fail-percent 0
head -c 300 "$tmp/d.png" >"$tmp/cut16.png"
expect png-16-truncated 2 "cut16.png" -- "$raytex" diff "$tmp/cut16.png" "$tmp/a.png"

# Metadata: the basic set is the same for every render of a view (byte-identical files); full
# adds where and when it ran.
render -o "$tmp/b.png" && render -o "$tmp/b.exr"
check png-byte-identical cmp -s "$tmp/a.png" "$tmp/b.png"
check exr-byte-identical cmp -s "$tmp/a.exr" "$tmp/b.exr"
check png-metadata grep -qa 'raytex 0.1.0' "$tmp/a.png"
check png-metadata-basic-only bash -c "! grep -qa 'Render time' '$tmp/a.png'"
render -o "$tmp/f.png" --metadata full && render -o "$tmp/f.exr" --metadata full
check png-metadata-full grep -qa 'Render time' "$tmp/f.png"
check exr-metadata-full grep -qa "$scene" "$tmp/f.exr"

# Passes: layers of an EXR; beside a PNG, PFM files and a PNG for albedo.
render -o "$tmp/p.exr" --filter box --aov uv,normal,depth,position,albedo,footprint,lod,octaves
for layer in uv.X normal.Z depth.Z position.Y albedo.R footprint.Y lod.Z octaves.Z normal.A; do
  check "exr-layer-$layer" grep -qa "$layer" "$tmp/p.exr"
done
render -o "$tmp/p.png" --aov normal,albedo,depth
check pass-files test -s "$tmp/p.normal.pfm" -a -s "$tmp/p.albedo.png" -a -s "$tmp/p.depth.pfm"
check pass-depth-grey test "$(head -c 2 "$tmp/p.depth.pfm")" = Pf
expect pass-box-only 2 '^raytex: --aov lod comes from the box filter' -- "$raytex" render "$scene" -o "$tmp/l.exr" --aov lod
check pass-box-only-nothing test ! -e "$tmp/l.exr"
expect pass-unknown 2 "unknown pass 'colour'" -- "$raytex" render "$scene" -o "$tmp/l.exr" --aov colour

# Unknown extensions and format options for another format: exit 2, nothing written.
expect unknown-extension 2 "unknown output format \(supported: .png, .exr, .pfm\)" -- render -o "$tmp/x.jpg"
check unknown-extension-nothing test ! -e "$tmp/x.jpg"
expect depth-not-png 2 '^raytex: --depth applies to a PNG output$' -- render -o "$tmp/x.exr" --depth 16
expect half-not-exr 2 '^raytex: --half applies to an EXR output$' -- render -o "$tmp/x.png" --half

# Several scenes into a directory in another format.
mkdir -p "$tmp/dir"
expect batch-exr 0 '' -- "$raytex" render "$scene" "$src/scenes/horizon.cfg" -o "$tmp/dir/" --format exr "${size[@]}"
check batch-exr-files test -s "$tmp/dir/textures.exr" -a -s "$tmp/dir/horizon.exr"

# render --compare: 0 within the limits, 3 over one (the image written all the same), 2 for a
# reference that cannot be read, and the comparison's options only with --compare.
expect compare-pass 0 'RMSE' -- render -o "$tmp/c.png" --compare "$tmp/a.png" --fail-rmse 0
expect compare-fail 3 'exceeds --fail-rmse 0.001' -- render -o "$tmp/c2.png" --filter box --compare "$tmp/a.png" --fail-rmse 0.001
check compare-fail-written test -s "$tmp/c2.png"
expect compare-missing 2 "$tmp/none.png" -- render -o "$tmp/c3.png" --compare "$tmp/none.png"
expect compare-options-alone 2 '^raytex: --fail-rmse applies to raytex diff and to render with --compare$' -- \
  render -o "$tmp/c4.png" --fail-rmse 1
expect compare-stdout 2 '^raytex: --compare reads the one output file back' -- render -o - --compare "$tmp/a.png"

finish
