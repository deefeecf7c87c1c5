// Passes (AOVs): per-pixel values besides the shaded colour, written with --aov. One table
// (passes.cpp) names each, its channels and where it may go; the bits are AOV_* of
// shaders/common.h. Definitions for users: docs/outputs.md. No Vulkan.
#pragma once

#include "common.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

enum class Pass : uint32_t {
  Uv = AOV_UV,
  Normal = AOV_NORMAL,
  Depth = AOV_DEPTH,
  Position = AOV_POSITION,
  Albedo = AOV_ALBEDO,
  Footprint = AOV_FOOTPRINT,
  Lod = AOV_LOD,
  Octaves = AOV_OCTAVES,
};

struct PassInfo {
  Pass pass;
  const char* name;      // as --aov, the EXR layer and the file suffix name it: "normal"
  int channels;          // values per pixel (1 to 3), besides the coverage alpha
  const char* channelNames;  // one letter per channel, EXR's convention: "XYZ", "RGB", "Z"
  bool fitsUnit;         // its values lie in [0, 1]: beside a PNG it is a PNG, else a PFM
  bool fullFloat;        // never written as half (--half): position
  bool boxFilterOnly;    // comes from the box filter: refused with --filter point
};

// The table, in bit order.
const std::vector<PassInfo>& passTable();
const PassInfo& passInfo(Pass pass);

// "uv,normal,depth": the passes named, in bit order, without repeats. Throws UsageError
// naming an unknown pass and listing the known ones.
std::vector<Pass> parsePassList(const std::string& flag, const std::string& text);

// Bit (1 << AOV_*) per pass.
uint32_t passMask(const std::vector<Pass>& passes);

// The position pass (AOV_POSITION) in world coordinates. The kernel writes hits relative to the
// camera (every GPU position is: common.h, Frame); the eye is added here in double, so each
// coordinate is rounded to float once, after the sum. `pixels` vec4s of the position pass
// (passPixels(renderer, Pass::Position): xyz camera-relative, coverage in w) with `eye` added
// where w is 1; background pixels (w 0) stay (0, 0, 0, 0).
std::vector<float> worldPositions(const float* cameraRelative, size_t pixels, const glm::dvec3& eye);
