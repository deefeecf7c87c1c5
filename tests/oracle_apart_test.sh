#!/usr/bin/env bash
# The GPU path never includes the float64 oracle's files (mapping.h, noise.h, texture.h,
# reference.h, reference_render.h): facts both sides need are shared as data (noise_permutation.h,
# plane_frame.h, texture_kinds.h), so the oracle stays an independent check of the kernel.
# Usage: tests/oracle_apart_test.sh SOURCE_DIR
set -u
src=${1:?usage: oracle_apart_test.sh SOURCE_DIR}
failed=0
for file in gpu_scene kernel_key pipeline renderer resources device scene_images texture_kinds parser scene_limits \
  noise_permutation plane_frame; do
  for path in "$src/host/$file.h" "$src/host/$file.cpp"; do
    [ -f "$path" ] || continue
    if grep -nE '#include "(mapping|noise|texture|reference|reference_render)\.h"' "$path"; then
      echo "FAIL: ${path#"$src"/} includes an oracle header"
      failed=1
    fi
  done
done
[ "$failed" -eq 0 ] && echo "the GPU path includes no oracle header"
exit "$failed"
