// The coverage filter's edge classification (coverage.glsl): lists the pixels of the band whose
// centre sees another object, or another set of blocked lights, than one of its eight neighbours'
// centres (BINDING_EDGE_IDS, written by the main kernel), and sizes the edge pass's indirect
// dispatch. A straight edge that crosses a pixel separates its centre from a neighbour's (the
// diagonal neighbour lies sqrt(2) pixels across), so every pixel it crosses is listed; a feature
// narrower than a pixel that no centre sees is not.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "common.h"

layout(local_size_x = WORKGROUP_X, local_size_y = WORKGROUP_Y) in;

layout(std140, binding = BINDING_FRAME) uniform FrameBlock { Frame frame; };
layout(std430, binding = BINDING_EDGE_IDS) readonly buffer EdgeIdBlock { uvec2 edgeIds[]; };
layout(std430, binding = BINDING_EDGE_LIST) buffer EdgeListBlock {
  uvec4 edgeHeader;  // x: workgroups of the edge pass (y, z: 1), w: pixels listed
  uint edgePixels[];
};

// Each invocation classifies a block of EDGE_BLOCK x EDGE_BLOCK pixels from the entries of the
// block and its one-pixel border, loaded once (on lavapipe the loads are most of the cost: a
// pixel a load took 4.5 ms at 640x480, one ninth of the loads per pixel of one invocation a
// pixel). Entries past the band's edge are clamped into it (the pixel itself or its neighbour
// along the edge: no difference), and pixels past it are not listed. No branch before the
// append: on lavapipe a storage-buffer load inside control flow is a loop over the SIMD lanes.
// The loops are unrolled, so that the entries stay in registers (lavapipe indexes a private
// array per lane through memory).
const int SIDE = EDGE_BLOCK + 2;

void main() {
  ivec2 size = ivec2(frame.width, frame.bandRows);
  ivec2 corner = ivec2(gl_GlobalInvocationID.xy) * EDGE_BLOCK;
  uvec2 seen[SIDE * SIDE];
  [[unroll]] for (int k = 0; k < SIDE * SIDE; ++k) {
    ivec2 q = clamp(corner + ivec2(k % SIDE - 1, k / SIDE - 1), ivec2(0), size - 1);
    seen[k] = edgeIds[q.y * size.x + q.x];
  }
  uint listed = 0u;  // bit j: pixel j of the block, row by row
  [[unroll]] for (int j = 0; j < EDGE_BLOCK * EDGE_BLOCK; ++j) {
    ivec2 c = ivec2(j % EDGE_BLOCK + 1, j / EDGE_BLOCK + 1);
    uvec2 centre = seen[c.y * SIDE + c.x];
    uint differs = 0u;  // not ||, which glslang turns into a branch
    [[unroll]] for (int k = 0; k < 9; ++k)
      differs |= uint(any(notEqual(seen[(c.y + k / 3 - 1) * SIDE + c.x + k % 3 - 1], centre)));
    ivec2 p = corner + c - 1;
    listed |= (differs & uint(p.x < size.x) & uint(p.y < size.y)) << uint(j);
  }
  if (listed == 0u) return;
  uint slot = atomicAdd(edgeHeader.w, uint(bitCount(listed)));
  atomicMax(edgeHeader.x, (slot + uint(bitCount(listed)) - 1u) / EDGE_GROUP_SIZE + 1u);
  for (int j = 0; j < EDGE_BLOCK * EDGE_BLOCK; ++j)
    if ((listed & (1u << uint(j))) != 0u) edgePixels[slot++] = uint((corner.y + j / EDGE_BLOCK) * size.x + corner.x + j % EDGE_BLOCK);
}
