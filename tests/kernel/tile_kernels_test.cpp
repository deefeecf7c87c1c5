// Tile kernels (host/gpu/tile_kernels.h) on the device: a frame split among kernels specialised to
// the kinds of their tiles renders, bit for bit, what the one kernel of the scene renders.
#include "support/files.h"
#include "support/gpu_fixture.h"
#include "gpu_scene.h"
#include "parser.h"
#include "support/sphere_field.h"
#include "tile_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

// The course scene with `material` on a sphere of `radius`, seen from `eye`.
Scene course(const std::string& material, double radius, const std::string& eye) {
  const std::string text = "#include \"texture_include.cfg\"\n"
                           "camera { eye = " + eye + "; lookat = (0, -0.5, 0); up = (0, 1, 0); fov = 35; }\n"
                           "light { position = (-6, 10, 6); color = (1, 1, 1); }\n"
                           "sphere { center = (0, 0, 0); radius = " + std::to_string(radius) + "; " + material + "; }\n"
                           "plane { normal = (0, 1, 0); distance = -2; tex_scale = 5; aChecker; }\n";
  return parseSceneText(text, kSourceDir + "/scenes/tile-kernels-test.cfg");
}

struct Render {
  uint32_t samplesPerSide = 1;
  uint32_t filter = FILTER_POINT;
  bool baked = false;
  bool progressive = false;
};

class TileKernelsTest : public RenderTest {
 protected:
  // Renders `g` with its one kernel, or with the kernels of `plan`. The output (and the sums)
  // are filled with NaN first, so a pixel no kernel writes shows.
  std::vector<float> renderWith(const GpuScene& g, const Render& how, const TilePlan* plan) {
    renderer_->accumulate = how.progressive;
    uploadScene(*renderer_, g);
    KernelOptions kernel;
    kernel.textureFilter = how.filter;
    kernel.samplesPerSide = how.samplesPerSide;
    kernel.bakeValues = how.baked;
    kernel.progressive = how.progressive;
    const KernelKey key = kernelKey(g, kernel);
    if (plan) prepareTileKernels(*renderer_, key, *plan);
    else preparePipeline(*renderer_, key);
    const size_t floats = size_t(g.frame.width) * g.frame.height * 4;
    std::fill_n(static_cast<float*>(renderer_->pixels.data), floats, NAN);
    if (how.progressive) std::fill_n(static_cast<float*>(renderer_->accumulation.data), floats, NAN);
    const uint32_t samples = how.progressive ? how.samplesPerSide * how.samplesPerSide : 1;
    for (uint32_t i = 0; i < samples; ++i) {
      if (how.progressive) renderSample(*renderer_, i);
      else renderFrame(*renderer_);
    }
    readbackFrame(*renderer_);
    const float* pixels = framePixels(*renderer_);
    std::vector<float> image(pixels, pixels + floats);
    renderer_->accumulate = false;
    return image;
  }

  // Floats (NaN included) where the tile kernels' image differs from the one kernel's.
  size_t differences(const GpuScene& g, const Render& how, const TilePlan& plan) {
    std::vector<float> tiles = renderWith(g, how, &plan);
    std::vector<float> one = renderWith(g, how, nullptr);
    size_t n = 0;
    for (size_t i = 0; i < one.size(); ++i) n += !(tiles[i] == one[i]);
    return n;
  }

  static TilePlan planFor(const GpuScene& g) {
    return planTileKernels(g, {g.shape.sphereKinds, g.shape.planeKinds});
  }
};

}  // namespace

// Every course material on a small sphere from the course's eye (built around the scene's
// values, point-sampled) and on a large one from low and to the side (box-filtered).
TEST_F(TileKernelsTest, CourseScenesRenderWhatTheOneKernelRenders) {
  const char* materials[] = {"aChecker", "aSolidChecker", "aNoise", "aMarble", "aWood", "anImage", "aTurbulence",
                             "aDturbulence"};
  for (const char* material : materials) {
    SCOPED_TRACE(material);
    const GpuScene small = buildGpuScene(course(material, 0.2, "(0, 3, 12)"), 96, 64);
    const GpuScene large = buildGpuScene(course(material, 2.0, "(7, -1, 5)"), 96, 64);
    // aChecker too: the floor's tiles skip the sphere's latitude and longitude.
    ASSERT_EQ(planFor(small).kernels.size(), 2u);
    ASSERT_EQ(planFor(large).kernels.size(), 2u);
    EXPECT_EQ(differences(small, {1, FILTER_POINT, true}, planFor(small)), 0u);
    EXPECT_EQ(differences(large, {1, FILTER_BOX}, planFor(large)), 0u);
  }
}

// Fields of spheres of all eight materials (the loop kernel at 8, the tree's with its tile lists
// above), orbiting views and one from inside a sphere; one sample, box-filtered, 2 x 2 samples
// in one dispatch and progressively.
TEST_F(TileKernelsTest, FieldsRenderWhatTheOneKernelRenders) {
  const struct {
    int spheres;
    const char* eye;
    Render how;
  } cases[] = {{8, "(0, 1, 4)", {}},            {8, "(2, -1.9, 3)", {1, FILTER_BOX}},
               {150, "(0, 1, 4)", {2}},         {150, "(2, -1.9, 3)", {2, FILTER_POINT, false, true}},
               {1000, "(0, 1, 4)", {}},         {1000, "(0, 8, 2)", {1, FILTER_BOX}}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::to_string(c.spheres) + " spheres, eye " + c.eye);
    const GpuScene g = buildGpuScene(field(c.spheres, c.eye), 160, 96);
    const TilePlan plan = planFor(g);
    ASSERT_GE(plan.kernels.size(), 2u);
    EXPECT_EQ(differences(g, c.how, plan), 0u);
  }
  Scene inside = field(200, "(0, 1, 4)");
  inside.camera.eye = inside.spheres[7].center;
  inside.camera.lookat = inside.camera.eye + glm::dvec3(0.3, -0.2, -1.0);
  SCOPED_TRACE("inside a sphere");
  const GpuScene g = buildGpuScene(inside, 96, 64);
  EXPECT_EQ(differences(g, {}, planFor(g)), 0u);
}

// The viewer's kernels (the floor's kinds alone, and all) render the same too.
TEST_F(TileKernelsTest, TheViewersKernelsRenderWhatTheOneKernelRenders) {
  const GpuScene g = buildGpuScene(field(150, "(0, 1, 4)"), 160, 96);
  const TilePlan plan =
      assignTiles(sphereFreeTileKernels({g.shape.sphereKinds, g.shape.planeKinds}), tileKinds(g), g.tiles.columns);
  ASSERT_EQ(plan.kernels.size(), 2u);
  EXPECT_EQ(differences(g, {2, FILTER_POINT, false, true}, plan), 0u);
}

// The comparison can fail: a plan whose kernels lack the kinds the spheres carry renders them
// untextured.
TEST_F(TileKernelsTest, AKernelWithoutATilesKindChangesTheImage) {
  const GpuScene g = buildGpuScene(course("aMarble", 2.0, "(0, 3, 12)"), 96, 64);
  TilePlan plan = planFor(g);
  ASSERT_EQ(plan.kernels.size(), 2u);
  for (TileKernel& k : plan.kernels) k.kinds.sphere = 0;
  EXPECT_GT(differences(g, {}, plan), 1000u);
}

// A kernel with more tiles than one uniform block holds (TILE_ORDER_CHUNK) is dispatched in
// blocks: every one of its tiles is rendered.
TEST_F(TileKernelsTest, MoreTilesThanOneBlockHoldsAreAllRendered) {
  const GpuScene g = buildGpuScene(field(12, "(0, 1, 4)"), 1200, 1040);
  const TilePlan plan = planFor(g);
  ASSERT_GE(plan.kernels.size(), 2u);
  size_t largest = 0;
  for (const TileKernel& k : plan.kernels) largest = std::max(largest, k.tiles.size());
  ASSERT_GT(largest, size_t(TILE_ORDER_CHUNK));
  EXPECT_EQ(differences(g, {}, plan), 0u);
}
