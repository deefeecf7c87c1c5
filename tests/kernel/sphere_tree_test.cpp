// The sphere tree (shaders/sphere_tree.glsl, host/accel/gpu_tree.cpp) on the device: within the
// uniform blocks' sizes it renders exactly what the loop over every sphere renders, from any
// camera; over them (spheres and nodes in storage buffers) it hits what the float64
// reference hits.
#include "support/gpu_fixture.h"
#include "support/sphere_field.h"
#include "gpu_scene.h"
#include "support/long_shadow_lists.h"
#include "parser.h"
#include "reference.h"
#include "texture_kinds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace {

class SphereTreeTest : public RenderTest {
 protected:
  // Renders `g` (uploaded as is) with its own kernel; without `shadowLists`, its shadow rays
  // walk the tree.
  std::vector<float> renderPacked(const GpuScene& g, uint32_t mode, uint32_t filter, bool shadowLists = true) {
    uploadScene(*renderer_, g);
    KernelOptions kernel;
    kernel.outputMode = mode;
    kernel.textureFilter = filter;
    KernelKey key = kernelKey(g, kernel);
    key.shape.shadowLists &= uint32_t(shadowLists);
    preparePipeline(*renderer_, key);
    renderFrame(*renderer_);
    readbackFrame(*renderer_);
    const float* pixels = framePixels(*renderer_);
    return std::vector<float>(pixels, pixels + size_t(g.frame.width) * g.frame.height * 4);
  }

  // The scene packed for the loop over every sphere (in the scene's order, no tree).
  static GpuScene withoutTree(GpuScene g, const Scene& scene) {
    g.shape.sphereTree = SPHERE_TREE_NONE;
    g.shape.shadowLists = 0;
    g.treeNodes.clear();
    packCamera(g, scene, g.frame.width, g.frame.height);
    return g;
  }

  // Floats that differ between the tree's image and the loop's.
  size_t differences(const Scene& scene, uint32_t mode, uint32_t filter, uint32_t w, uint32_t h) {
    const GpuScene tree = buildGpuScene(scene, w, h);
    EXPECT_NE(tree.shape.sphereTree, uint32_t(SPHERE_TREE_NONE));
    std::vector<float> a = renderPacked(tree, mode, filter);
    std::vector<float> b = renderPacked(withoutTree(tree, scene), mode, filter);
    return differing(a, b);
  }

  // Floats that differ between the shadow lists' image and the tree's shadow walk's.
  size_t shadowDifferences(const Scene& scene, uint32_t w, uint32_t h) {
    const GpuScene g = buildGpuScene(scene, w, h);
    EXPECT_TRUE(g.shape.shadowLists);
    return differing(renderPacked(g, OUTPUT_SHADED, FILTER_POINT), renderPacked(g, OUTPUT_SHADED, FILTER_POINT, false));
  }

  static size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
  }
};

TEST_F(SphereTreeTest, RendersWhatTheLoopOverEverySphereRenders) {
  // The bench's view, orbiting views (some looking back over the field, the light behind), a
  // view from low down along the floor and one from inside a sphere.
  const std::string eyes[] = {"(0, 1, 4)", "(9, 2, -4)", "(-3, 0.5, -14)", "(2, -1.9, 3)", "(0, 8, 2)"};
  for (int n : {int(SPHERE_TREE_MIN_SPHERES), 150, 1000}) {
    for (const std::string& eye : eyes) {
      SCOPED_TRACE(std::to_string(n) + " spheres, eye " + eye);
      const Scene scene = field(n, eye);
      EXPECT_EQ(differences(scene, OUTPUT_SHADED, FILTER_POINT, 96, 64), 0u);
      EXPECT_EQ(differences(scene, OUTPUT_SHADED, FILTER_BOX, 96, 64), 0u);
    }
  }
  Scene inside = field(200, "(0, 1, 4)");
  const Sphere& s = inside.spheres[7];
  inside.camera.eye = s.center;
  inside.camera.lookat = s.center + glm::dvec3(0.3, -0.2, -1.0);
  SCOPED_TRACE("inside a sphere");
  EXPECT_EQ(differences(inside, OUTPUT_SHADED, FILTER_POINT, 96, 64), 0u);
  EXPECT_EQ(differences(inside, OUTPUT_COORDS, FILTER_POINT, 96, 64), 0u);
}

// The comparison can fail: a tree whose boxes lose a sphere renders another image (its shadow
// rays walking the tree: the tile lists leave primary rays none to walk here).
TEST_F(SphereTreeTest, ABoxThatMissesASphereChangesTheImage) {
  const Scene scene = field(150, "(0, 1, 4)");
  GpuScene g = buildGpuScene(scene, 96, 64);
  std::vector<float> right = renderPacked(g, OUTPUT_SHADED, FILTER_POINT, false);
  for (gpu::BvhNode& n : g.treeNodes)
    if (n.spheres != 0) n.hi = n.lo;  // every leaf box shrunk to a corner
  std::vector<float> wrong = renderPacked(g, OUTPUT_SHADED, FILTER_POINT, false);
  EXPECT_NE(right, wrong);
}

// And so can the tile lists': with every tile's list empty, primary rays miss the spheres.
TEST_F(SphereTreeTest, EmptyTileListsChangeTheImage) {
  const Scene scene = field(150, "(0, 1, 4)");
  GpuScene g = buildGpuScene(scene, 96, 64);
  ASSERT_TRUE(g.shape.tileLists);
  std::vector<float> right = renderPacked(g, OUTPUT_COORDS, FILTER_POINT);
  for (size_t t = 1; t < g.tiles.ranges.size(); t += 2) g.tiles.ranges[t] = 0;
  std::vector<float> wrong = renderPacked(g, OUTPUT_COORDS, FILTER_POINT);
  size_t spheres = 0;
  for (size_t i = 3; i < wrong.size(); i += 4) spheres += wrong[i] == float(HIT_SPHERE);
  EXPECT_NE(right, wrong);
  EXPECT_EQ(spheres, 0u);
}

// And so can their order: a ray stops at the first listed sphere whose nearest point lies beyond
// its hit, so lists reversed (farthest first) lose spheres that lie nearer.
TEST_F(SphereTreeTest, FarthestFirstTileListsChangeTheImage) {
  const Scene scene = field(150, "(0, 1, 4)");
  GpuScene g = buildGpuScene(scene, 96, 64);
  ASSERT_TRUE(g.shape.tileLists);
  const std::vector<float> right = renderPacked(g, OUTPUT_COORDS, FILTER_POINT);
  size_t reversed = 0;
  for (size_t t = 0; t < size_t(g.tiles.columns) * g.tiles.rows; ++t) {
    const uint32_t first = g.tiles.ranges[2 * t], count = g.tiles.ranges[2 * t + 1];
    if (count == TILE_USE_TREE || count < 2) continue;
    std::reverse(g.tiles.spheres.begin() + first, g.tiles.spheres.begin() + first + count);
    ++reversed;
  }
  ASSERT_GT(reversed, 0u);
  EXPECT_GT(differing(right, renderPacked(g, OUTPUT_COORDS, FILTER_POINT)), 100u);
}

// Shadow rays through the per-tile lists (shadow_lists.h) find what the tree's walk finds: the
// bench's field and one with four lights and two more planes (litField), from the views above.
TEST_F(SphereTreeTest, ShadowListsRenderWhatTheTreeWalkRenders) {
  const std::string eyes[] = {"(0, 1, 4)", "(9, 2, -4)", "(-3, 0.5, -14)", "(2, -1.9, 3)", "(0, 8, 2)"};
  for (int n : {int(SPHERE_TREE_MIN_SPHERES), 150, 1500}) {
    for (const std::string& eye : eyes) {
      SCOPED_TRACE(std::to_string(n) + " spheres, eye " + eye);
      EXPECT_EQ(shadowDifferences(field(n, eye), 128, 72), 0u);
      EXPECT_EQ(shadowDifferences(litField(n, eye), 128, 72), 0u);
    }
  }
  Scene inside = litField(200, "(0, 1, 4)");
  const Sphere& s = inside.spheres[7];
  inside.camera.eye = s.center;
  inside.camera.lookat = s.center + glm::dvec3(0.3, -0.2, -1.0);
  SCOPED_TRACE("inside a sphere");
  EXPECT_EQ(shadowDifferences(inside, 128, 72), 0u);
}

// The comparison can fail: with every shadow list emptied, the spheres cast no shadows.
TEST_F(SphereTreeTest, EmptyShadowListsChangeTheImage) {
  const Scene scene = litField(150, "(0, 1, 4)");
  GpuScene g = buildGpuScene(scene, 128, 72);
  ASSERT_TRUE(g.shape.shadowLists);
  const std::vector<float> right = renderPacked(g, OUTPUT_SHADED, FILTER_POINT);
  ASSERT_TRUE(g.tiles.shadowGrids.empty());  // under MAX_UNIFORM_SPHERES: no grids after the lists
  for (size_t t = g.tiles.shadowRanges + 1; t < g.tiles.ranges.size(); t += 2)
    if (g.tiles.ranges[t] != TILE_USE_TREE) g.tiles.ranges[t] = 0;
  EXPECT_GT(differing(right, renderPacked(g, OUTPUT_SHADED, FILTER_POINT)), 1000u);
}

// Shadow rays through the grids (shadow_grid.h; scenes over MAX_UNIFORM_SPHERES), every cell's
// list marked long so that each ray between a grid's plane and its light looks its grid up,
// find what the tree's walk finds.
TEST_F(SphereTreeTest, ShadowGridsRenderWhatTheTreeWalkRenders) {
  const std::string eyes[] = {"(0, 1, 4)", "(9, 2, -4)", "(-3, 0.5, -14)", "(2, -1.9, 3)", "(0, 8, 2)"};
  std::vector<std::pair<std::string, Scene>> scenes;
  for (int n : {1100, 4000})
    for (const std::string& eye : eyes) {
      scenes.emplace_back(std::to_string(n) + " spheres, eye " + eye, field(n, eye));
      scenes.emplace_back(std::to_string(n) + " spheres, four lights, eye " + eye, litField(n, eye));
    }
  Scene inside = litField(1100, "(0, 1, 4)");
  inside.camera.eye = inside.spheres[7].center;
  inside.camera.lookat = inside.camera.eye + glm::dvec3(0.3, -0.2, -1.0);
  scenes.emplace_back("inside a sphere", inside);
  for (const auto& [name, scene] : scenes) {
    SCOPED_TRACE(name);
    GpuScene g = buildGpuScene(scene, 128, 72);
    ASSERT_EQ(g.shape.sphereTree, uint32_t(SPHERE_TREE_STORAGE));
    ASSERT_TRUE(g.shape.shadowLists);
    markShadowListsLong(g);
    ASSERT_NE(g.frame.shadowGrids[0].rows, TILE_USE_TREE);  // the course's light has one
    EXPECT_EQ(differing(renderPacked(g, OUTPUT_SHADED, FILTER_POINT), renderPacked(g, OUTPUT_SHADED, FILTER_POINT, false)),
              0u);
  }
}

// The comparison can fail: with the course light's grid emptied, its shadows go.
TEST_F(SphereTreeTest, EmptyShadowGridsChangeTheImage) {
  GpuScene g = buildGpuScene(litField(1100, "(0, 1, 4)"), 128, 72);
  ASSERT_TRUE(g.shape.shadowLists);
  markShadowListsLong(g);
  const std::vector<float> right = renderPacked(g, OUTPUT_SHADED, FILTER_POINT);
  const gpu::ShadowGrid& grid = g.frame.shadowGrids[0];
  for (size_t c = 0; c < size_t(grid.columns) * grid.rows; ++c) g.tiles.ranges[grid.firstRange + 2 * c + 1] = 0;
  EXPECT_GT(differing(right, renderPacked(g, OUTPUT_SHADED, FILTER_POINT)), 100u);
}

// Over MAX_UNIFORM_SPHERES the spheres and nodes are read from storage buffers: each reliable
// pixel hits what the float64 reference hits, at its texture coordinate. Pixels near a
// silhouette (within 2e-3 of the ray's distance: near-ties for a float ray), on the far floor or
// at a pole are counted, not checked (1196 of 19200 here).
TEST_F(SphereTreeTest, StorageBuffersHitWhatTheReferenceHits) {
  const int w = 160, h = 120;
  const Scene scene = field(3000, "(0, 1, 4)");
  const GpuScene g = buildGpuScene(scene, w, h);
  ASSERT_EQ(g.shape.sphereTree, uint32_t(SPHERE_TREE_STORAGE));
  std::vector<float> gpu = renderPacked(g, OUTPUT_COORDS, FILTER_POINT);
  int checked[3] = {0, 0, 0}, nearTies = 0, wrongKind = 0;
  double worst = 0.0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::dvec3 d = referenceRayDirection(scene.camera, w, h, x, y);
      const ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, d, true);
      const float* p = &gpu[size_t(y * w + x) * 4];
      if (hit.edgeMargin < 2e-3 || (hit.kind == HIT_PLANE && hit.t > 60.0) ||
          (hit.kind == HIT_SPHERE && std::abs(hit.n.y) > 0.999)) {
        ++nearTies;
        continue;
      }
      if (int(p[3]) != hit.kind) {
        ++wrongKind;
        continue;
      }
      ++checked[hit.kind];
      if (hit.kind != HIT_SPHERE) continue;
      const Material& m = scene.materials[size_t(scene.spheres[hit.index].material)];
      const bool solid = isSolidTexture(m.texture.kind);
      for (int c = 0; c < (solid ? 3 : 2); ++c) {
        double ref = solid ? hit.tc.solid[c] : hit.tc.uv[c];
        double diff = std::abs(p[c] - ref);
        if (!solid) diff = std::min(diff, std::abs(1.0 - diff));  // u wraps at the seam
        worst = std::max(worst, diff);
      }
    }
  }
  RecordProperty("near_ties", nearTies);
  EXPECT_EQ(wrongKind, 0);
  EXPECT_GT(checked[HIT_SPHERE], w * h / 20);
  EXPECT_GT(checked[HIT_PLANE], w * h / 5);
  EXPECT_LT(nearTies, w * h / 10);
  EXPECT_LT(worst, 1e-3) << "largest texture-coordinate difference";
}

}  // namespace
