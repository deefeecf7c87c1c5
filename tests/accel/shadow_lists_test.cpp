// The shadow lists (host/accel/shadow_lists.cpp) are conservative: every sphere that blocks a
// pixel's shadow ray in float64 is listed for its cell and light (the device tests in
// sphere_tree_test.cpp render them against the tree's shadow walk).
#include "support/sphere_field.h"
#include "gpu_scene.h"
#include "support/packed_rays.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace {

// Whether sphere i is in the shadow list of (cell, light), or the cell walks the tree.
bool listed(const TileLists& lists, uint32_t lights, uint32_t cell, uint32_t light, uint32_t i) {
  const uint32_t* range = &lists.ranges[lists.shadowRanges + 2 * (size_t(cell) * lights + light)];
  if (range[1] == TILE_USE_TREE) return true;
  const auto first = lists.spheres.begin() + range[0], last = first + range[1];
  return std::find(first, last, i) != last;
}

}  // namespace

TEST(ShadowLists, EveryBlockingSphereIsListedForItsCellAndLight) {
  const uint32_t w = 240, h = 136;
  std::mt19937 rng{7};
  for (const std::string eye : {"(0, 1, 4)", "(9, 2, -4)", "(-3, 0.5, -14)", "(0, 8, 2)"}) {
    SCOPED_TRACE("eye " + eye);
    const Scene scene = litField(300, eye);
    PackOptions options;
    options.mipmaps = false;
    const GpuScene g = buildGpuScene(scene, w, h, options);
    ASSERT_TRUE(g.shape.shadowLists);
    const TileLists& lists = g.tiles;
    const uint32_t lights = uint32_t(g.lights.size());
    const uint32_t cells = lists.shadowColumns * lists.shadowRows;
    ASSERT_EQ(lists.shadowColumns, (lists.columns + SHADOW_CELL - 1) / SHADOW_CELL);
    ASSERT_EQ(lists.ranges.size(), lists.shadowRanges + 2 * size_t(cells) * lights);
    int blocked = 0, missing = 0, walks = 0;
    for (uint32_t c = 0; c < cells; ++c)  // for the course's light
      walks += lists.ranges[lists.shadowRanges + 2 * c * lights + 1] == TILE_USE_TREE;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        // A point anywhere in the pixel (the samples of --spp), camera-relative.
        glm::dvec3 point;
        if (!firstHit(g, x, y, w, h, rng, point)) continue;
        const uint32_t cell = (y / (TILE_SIZE * SHADOW_CELL)) * lists.shadowColumns + x / (TILE_SIZE * SHADOW_CELL);
        for (uint32_t l = 0; l < lights; ++l) {
          const glm::dvec3 toLight = glm::dvec3(g.lights[l].position) - point;
          const double distance = glm::length(toLight);
          for (uint32_t i = 0; i < g.spheres.size(); ++i) {
            // Offset from the surface, as the kernel's shadow rays are (a sphere's own far side is
            // not a blocker).
            const glm::dvec3 dir = toLight / distance;
            if (!(sphereDistance(point + 1e-6 * distance * dir, dir, g.spheres[i]) < distance)) continue;
            ++blocked;
            missing += !listed(lists, lights, cell, l, i);
          }
        }
      }
    EXPECT_EQ(missing, 0);
    EXPECT_GT(blocked, int(w * h / 20));
    EXPECT_LT(walks, int(cells / 4));  // most cells have lists
  }
}
