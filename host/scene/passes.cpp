#include "passes.h"

#include "error.h"

#include <algorithm>

const std::vector<PassInfo>& passTable() {
  static const std::vector<PassInfo> table = {
      {Pass::Uv, "uv", 3, "XYZ", false, false, false},
      {Pass::Normal, "normal", 3, "XYZ", false, false, false},
      {Pass::Depth, "depth", 1, "Z", false, false, false},
      {Pass::Position, "position", 3, "XYZ", false, true, false},
      {Pass::Albedo, "albedo", 3, "RGB", true, false, false},
      {Pass::Footprint, "footprint", 2, "XY", false, false, true},
      {Pass::Lod, "lod", 1, "Z", false, false, true},
      {Pass::Octaves, "octaves", 1, "Z", false, false, true},
  };
  return table;
}

const PassInfo& passInfo(Pass pass) { return passTable()[uint32_t(pass)]; }

std::vector<Pass> parsePassList(const std::string& flag, const std::string& text) {
  std::vector<Pass> passes;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    auto it = std::find_if(passTable().begin(), passTable().end(),
                           [&](const PassInfo& p) { return name == p.name; });
    if (it == passTable().end()) {
      std::string known;
      for (const PassInfo& p : passTable()) known += (known.empty() ? "" : ", ") + std::string(p.name);
      throw UsageError(flag + ": unknown pass '" + name + "' (passes: " + known + ")");
    }
    if (std::find(passes.begin(), passes.end(), it->pass) == passes.end()) passes.push_back(it->pass);
    start = end + 1;
  }
  std::sort(passes.begin(), passes.end());
  return passes;
}

uint32_t passMask(const std::vector<Pass>& passes) {
  uint32_t mask = 0;
  for (Pass p : passes) mask |= 1u << uint32_t(p);
  return mask;
}

std::vector<float> worldPositions(const float* cameraRelative, size_t pixels, const glm::dvec3& eye) {
  std::vector<float> world(cameraRelative, cameraRelative + pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    float* p = &world[i * 4];
    if (p[3] == 0.0f) continue;  // the background: no position
    for (int c = 0; c < 3; ++c) p[c] = float(double(p[c]) + eye[c]);
  }
  return world;
}
