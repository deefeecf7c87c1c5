// Stability: texture cells across the axes. A checker computed with int()
// truncation merges the cells [-1, 0) and [0, 1) into one twice as wide; every cell must be
// one unit wide on both sides of x = 0 and z = 0, and match the double reference.
#include "reference.h"
#include "reference_render.h"
#include "texture.h"
#include "texture_kinds.h"

#include "support/stability_fixture.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace {

// --- 1. negative-quadrant checker ----------------------------------------

// Unit checks on y = 0 seen straight from above (checkerFloorScene), the view centred
// near the origin so that x = 0 and z = 0 cross the image. Check edges fall exactly on
// pixel borders, 20 px per unit: every check is 20 px wide and every pixel centre is half
// a pixel (0.025 units) from an edge, far beyond float error (~1e-6 units), so a run may
// differ from 20 px only through the rounding of the field of view (+-1 px allowed;
// measured: all exactly 20). int() truncation would merge the cells [-1, 0) and [0, 1):
// a 40 px run on every row and column.
TEST_F(StabilityTest, NegativeQuadrantCheckerHasEqualCells) {
  const int w = 160, h = 120;
  Scene scene = checkerFloorScene();
  std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);

  // Runs of equal colour; the first and last of a line are cut by the image border.
  auto checkRuns = [&](bool rows) {
    const int lines = rows ? h : w, length = rows ? w : h;
    int internalRuns = 0, badRuns = 0, shortest = 1 << 30, longest = 0;
    for (int line = 0; line < lines; ++line) {
      std::vector<int> runs;
      float last = -1.0f;
      for (int k = 0; k < length; ++k) {
        size_t i = rows ? size_t(line) * w + k : size_t(k) * w + line;
        float red = gpu[i * 4];
        if (k == 0 || red != last) runs.push_back(0);
        ++runs.back();
        last = red;
      }
      for (size_t r = 1; r + 1 < runs.size(); ++r) {
        ++internalRuns;
        shortest = std::min(shortest, runs[r]);
        longest = std::max(longest, runs[r]);
        if (std::abs(runs[r] - 20) > 1) ++badRuns;
      }
    }
    // x in [-3.5, 4.5]: 7 whole cells per row; z in [-2.7, 3.3]: 5 per column.
    EXPECT_EQ(internalRuns, rows ? 7 * h : 5 * w) << (rows ? "rows" : "columns");
    EXPECT_EQ(badRuns, 0) << (rows ? "rows" : "columns") << ": runs from " << shortest << " to "
                          << longest << " px, want 20 +- 1";
  };
  checkRuns(true);   // every row crosses x = 0
  checkRuns(false);  // every column crosses z = 0

  // Parity per pixel against the double reference (textureColorReference). The colours
  // are exact (mix with t = 0 or 1), so they must match to float rounding of the colour.
  std::vector<ReferenceHit> ref = referenceHits(scene, w, h);
  const TextureDesc& tex = scene.materials[0].texture;
  int checked = 0, mismatches = 0, negative = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    const ReferenceHit& hit = ref[i];
    ASSERT_EQ(hit.kind, HIT_PLANE);
    glm::dvec2 unwrapped = hit.tc.uv + hit.tc.tile;
    auto nearEdge = [](double x) { return std::abs(x - std::round(x)) < 1e-3; };
    if (nearEdge(unwrapped.x) || nearEdge(unwrapped.y)) continue;
    ++checked;
    if (unwrapped.x < 0.0 || unwrapped.y < 0.0) ++negative;
    glm::dvec3 expected = textureColorReference(tex, hit.tc);
    for (int c = 0; c < 3; ++c)
      if (std::abs(gpu[i * 4 + c] - expected[c]) > 1e-6) {
        ++mismatches;
        break;
      }
  }
  EXPECT_EQ(checked, w * h);  // no pixel centre lies within 1e-3 of an edge
  EXPECT_GT(negative, w * h / 3);
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
