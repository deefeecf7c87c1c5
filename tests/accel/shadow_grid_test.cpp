// The shadow grids (host/accel/shadow_grid.cpp) are conservative: with every cell's list long, for
// a point between a light's grid plane and half the light's height, looked up in float as the
// kernel does, every sphere that blocks its shadow ray in float64 is listed (the device tests
// in sphere_tree_test.cpp render through them against the tree's shadow walk).
#include "support/sphere_field.h"
#include "gpu_scene.h"
#include "support/packed_rays.h"
#include "support/long_shadow_lists.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace {

// The kernel's lookup (shaders/sphere_tree.glsl, shadowGridRange) in float: false where the
// light has no grid or the point lies outside the grid's reach, else the cell's range, empty
// past the grid's edge.
bool gridRange(const GpuScene& g, uint32_t light, glm::vec3 o, glm::vec3 d, float tMax, uint32_t& first,
               uint32_t& count) {
  const gpu::ShadowGrid& grid = g.tiles.shadowGrids[light];
  if (grid.rows == TILE_USE_TREE) return false;
  const gpu::Plane& p = g.planes[grid.plane];
  const glm::vec3 n(p.normalDistance);
  const float height = glm::dot(n, o) - p.normalDistance.w, rise = glm::dot(n, d);
  if (!(height >= 0.0f && rise > 0.0f && height <= rise * tMax)) return false;
  const glm::vec3 q = o - d * (height / rise);
  const float u = (glm::dot(q, glm::vec3(p.tangentScale)) - grid.corner.x) * grid.corner.z;
  const float v = (glm::dot(q, glm::vec3(p.binormal)) - grid.corner.y) * grid.corner.z;
  count = 0;
  if (!(u >= 0.0f && v >= 0.0f && u < float(grid.columns) && v < float(grid.rows))) return true;
  const size_t range = grid.firstRange + 2 * (size_t(v) * grid.columns + size_t(u));
  first = g.tiles.ranges[range], count = g.tiles.ranges[range + 1];
  return true;
}

// The scene moved by `offset`, camera and lights too.
Scene moved(Scene scene, glm::dvec3 offset) {
  scene.camera.eye += offset, scene.camera.lookat += offset;
  for (Sphere& s : scene.spheres) s.center += offset;
  for (Light& l : scene.lights) l.position += offset;
  for (Plane& p : scene.planes) p.distance += glm::dot(p.normal, offset);
  return scene;
}

struct Counts {
  int blocked = 0, missing = 0, lookups = 0;
};

// Looks up the shadow ray of the first hit in each pixel of g's view (at a random point in
// it) for every light, and checks the blockers.
Counts checkPixels(const GpuScene& g, uint32_t w, uint32_t h, std::mt19937& rng) {
  Counts c;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      glm::dvec3 point;
      if (!firstHit(g, x, y, w, h, rng, point)) continue;
      for (uint32_t l = 0; l < g.lights.size(); ++l) {
        const glm::dvec3 toLight = glm::dvec3(g.lights[l].position) - point;
        const double distance = glm::length(toLight);
        const glm::dvec3 dir = toLight / distance;
        // Offset from the surface, as the kernel's shadow rays are.
        const glm::dvec3 origin = point + 1e-6 * distance * dir;
        uint32_t first = 0, count = 0;
        if (!gridRange(g, l, glm::vec3(origin), glm::vec3(dir), float(distance), first, count)) continue;
        ++c.lookups;
        const auto begin = g.tiles.spheres.begin() + first, end = begin + count;
        for (uint32_t i = 0; i < g.spheres.size(); ++i) {
          if (!(sphereDistance(origin, dir, g.spheres[i]) < distance)) continue;
          ++c.blocked;
          c.missing += std::find(begin, end, i) == end;
        }
      }
    }
  return c;
}

}  // namespace

TEST(ShadowGrids, EveryBlockingSphereIsListedForTheCellItsRayLandsIn) {
  const uint32_t w = 240, h = 136;
  std::mt19937 rng{11};
  PackOptions options;
  options.mipmaps = false;
  for (const glm::dvec3 offset : {glm::dvec3(0.0), glm::dvec3(3e5, 0.0, -1e6)})
    for (const std::string eye : {"(0, 1, 4)", "(9, 2, -4)", "(-3, 0.5, -14)", "(0, 8, 2)"}) {
      SCOPED_TRACE("eye " + eye + ", moved by " + std::to_string(offset.x) + ", " + std::to_string(offset.z));
      GpuScene g = buildGpuScene(moved(litField(300, eye), offset), w, h, options);
      ASSERT_TRUE(g.shape.shadowLists);
      markShadowListsLong(g);
      ASSERT_EQ(g.tiles.shadowGrids.size(), g.lights.size());
      // The light among the spheres has none (spheres reach above it, so no plane has bounded
      // shadows); the others have grids on the floor.
      for (uint32_t l : {0, 2, 3}) EXPECT_EQ(g.tiles.shadowGrids[l].plane, 0u);
      EXPECT_NE(g.tiles.shadowGrids[0].rows, TILE_USE_TREE);
      EXPECT_EQ(g.tiles.shadowGrids[1].rows, TILE_USE_TREE);
      EXPECT_NE(g.tiles.shadowGrids[2].rows, TILE_USE_TREE);
      EXPECT_NE(g.tiles.shadowGrids[3].rows, TILE_USE_TREE);
      const Counts c = checkPixels(g, w, h, rng);
      EXPECT_EQ(c.missing, 0);
      EXPECT_GT(c.lookups, int(w * h / 2));
      EXPECT_GT(c.blocked, int(w * h / 50));
    }
}
