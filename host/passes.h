// Passes (AOVs): per-pixel values besides the shaded colour, written with --aov. One table
// (passes.cpp) names each, its channels and where it may go; the bits are AOV_* of
// shaders/common.h. Definitions for users: docs/outputs.md. No Vulkan.
#pragma once

#include "common.h"

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
