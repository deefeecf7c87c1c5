// The trace kernel's build variants: shaders/trace.comp.glsl compiled with the defines of a row,
// so that code a variant never runs is not in its module at all (specialisation constants remove
// code only after the driver has processed it, which slows pipeline creation on lavapipe:
// docs/performance.md, "Start-up"). One row each, read by CMake, which compiles each row twice
// (trace_<name>, and trace_<name>_tree with RAYTEX_SPHERE_TREE: the sphere tree's walks and the
// tile and shadow lists), and by traceVariant (pipeline.cpp), which picks the row a key needs.
//
// RAYTEX_TRACE_VARIANTS(X) calls X(name, FILTER_BOX, SUPERSAMPLE, DEBUG_OUTPUT, AOV, EDGE_PASS):
// 1 where the variant is compiled with RAYTEX_<that>, else 0.
#pragma once

// clang-format off
#define RAYTEX_TRACE_VARIANTS(X) \
  /* name          FILTER_BOX SUPERSAMPLE DEBUG_OUTPUT AOV EDGE_PASS */ \
  /* the shaded image, one sample per dispatch, point or box textures */ \
  X(point,         0,         0,          0,           0,  0) \
  X(box,           1,         0,          0,           0,  0) \
  /* N x N samples in one dispatch */ \
  X(point_samples, 0,         1,          0,           0,  0) \
  X(box_samples,   1,         1,          0,           0,  0) \
  /* OUTPUT_COORDS and OUTPUT_ALBEDO, the outputs the tests compare with the reference */ \
  X(debug,         0,         0,          1,           0,  0) \
  /* with passes, one sample or N x N */ \
  X(aov_point,     0,         0,          0,           1,  0) \
  X(aov_box,       1,         0,          0,           1,  0) \
  /* FILTER_COVERAGE's edge pass */ \
  X(edges,         1,         0,          0,           0,  1)
// clang-format on
