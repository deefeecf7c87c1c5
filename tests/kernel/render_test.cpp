// Image tests on a Vulkan device (lavapipe in CI), validation layers on:
// - the eight course materials against golden PNGs (tests/golden/),
// - per-pixel checks of the kernel's texture coordinates and texture colours
//   against the CPU double-precision reference (host/reference/reference.cpp, mapping.cpp,
//   texture.cpp), independent of any golden.
#include "support/course_scene.h"
#include "support/files.h"
#include "support/gpu_fixture.h"
#include "support/reference_pixels.h"
#include "support/image_diff.h"
#include "gpu_scene.h"
#include "flip.h"
#include "image_file.h"
#include "srgb.h"
#include "image_metrics.h"
#include "output_formats.h"
#include "atomic_file.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"
#include "renderer.h"
#include "texture.h"
#include "texture_kinds.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace {

const char* const kMaterials[] = {"aSolidChecker", "aChecker", "aNoise",      "aMarble",
                                  "aWood",         "anImage",  "aTurbulence", "aDturbulence"};

// --- goldens ---------------------------------------------------------------

class GoldenTest : public RenderTest, public ::testing::WithParamInterface<const char*> {};

// Small renders of the course scene, one per sphere material. The goldens were
// looked at before committing; RAYTEX_UPDATE_GOLDENS=1 rewrites them (look again).
TEST_P(GoldenTest, CourseSceneMatchesGolden) {
  const std::string material = GetParam();
  const uint32_t w = 160, h = 120;
  std::vector<float> pixels = render(courseScene(material), w, h, OUTPUT_SHADED);
  size_t nonFinite = 0;
  ImageRGBA8 actual = encodeSrgb(pixels.data(), int(w), int(h), &nonFinite);
  EXPECT_EQ(nonFinite, 0u);

  const std::string golden = kSourceDir + "/tests/golden/" + material + ".png";
  const char* update = getenv("RAYTEX_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    writePngAtomic(golden, actual);
    GTEST_SKIP() << "wrote " << golden << ": look at it before committing";
  }
  // Compared as raytex diff compares: the golden PNG decoded to linear, the render's floats
  // clamped to [0, 1] as an 8-bit image is. The golden's 8-bit rounding alone gives a mean FLIP
  // of about 0.007 and no pixel over 0.05; another filter or texture gives 0.1 and a quarter of
  // the pixels. Edge pixels may flip between drivers or CPUs (float rounding at a check or
  // silhouette edge), so a few pixels may differ by more.
  LinearImage expected;
  ASSERT_NO_THROW(expected = readLinearImage(golden, uint64_t(1) << 30));
  LinearImage rendered{rgbFloatImage(pixels.data(), int(w), int(h)), false};
  clampForComparison(expected, rendered);
  const ImageMetrics m = measureImages(expected.image, rendered.image, 0.05);
  const FloatImage flip = flipErrorMap(linearToSrgbImage(expected.image), linearToSrgbImage(rendered.image));
  const double flipMeanError = flipMean(flip);
  const bool ok = flipMeanError <= 0.02 && m.shareOver <= 1.0 / 400.0;
  if (!ok) {
    writePngAtomic((testOutputDir() / (material + "_actual.png")).string(), actual);
    writePngAtomic((testOutputDir() / (material + "_flip.png")).string(), flipHeatmap(flip));
  }
  EXPECT_TRUE(ok) << material << ": mean FLIP " << flipMeanError << ", " << 100.0 * m.shareOver
                  << "% of the pixels over 0.05 (linear); see " << testOutputDir().string();
}

INSTANTIATE_TEST_SUITE_P(Materials, GoldenTest, ::testing::ValuesIn(kMaterials),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

// --- analytic checks against the CPU double reference ----------------------

struct PixelRef {
  ReferenceHit hit;
  bool reliable;  // away from silhouettes, poles and the far horizon
};

std::vector<PixelRef> referenceImage(const Scene& scene, int w, int h) {
  std::vector<PixelRef> out;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      glm::dvec3 d = referenceRayDirection(scene.camera, w, h, x, y);
      PixelRef ref{referenceClosestHit(scene, glm::dvec3(scene.camera.eye), d), true};
      // A float ray may land on the other side of a silhouette; near the horizon a
      // pixel spans many texture tiles; at the poles u is ill-conditioned.
      if (ref.hit.edgeMargin < 2e-3) ref.reliable = false;
      if (ref.hit.kind == HIT_PLANE && ref.hit.t > 60.0) ref.reliable = false;
      if (ref.hit.kind == HIT_SPHERE && std::abs(ref.hit.n.y) > 0.999) ref.reliable = false;
      out.push_back(ref);
    }
  }
  return out;
}

// Kernel texture coordinates (OUTPUT_COORDS) equal the notes' formulas evaluated in double.
TEST_F(RenderTest, TextureCoordinatesMatchDoubleReference) {
  const int w = 128, h = 96;
  for (const char* material : {"aChecker", "aSolidChecker"}) {
    SCOPED_TRACE(material);
    Scene scene = courseScene(material);
    std::vector<float> gpu = render(scene, w, h, OUTPUT_COORDS);
    std::vector<PixelRef> ref = referenceImage(scene, w, h);
    int checked[3] = {0, 0, 0}, wrongKind = 0;
    double worst = 0.0;
    for (int i = 0; i < w * h; ++i) {
      const ReferenceHit& hit = ref[i].hit;
      const float* g = &gpu[size_t(i) * 4];
      if (!ref[i].reliable) continue;
      if (int(g[3]) != hit.kind) {
        ++wrongKind;
        continue;
      }
      if (hit.kind == HIT_NONE) {
        ++checked[0];
        continue;
      }
      ++checked[hit.kind];
      const Material& m = scene.materials[size_t(hit.kind == HIT_PLANE ? scene.planes[hit.index].material
                                                                        : scene.spheres[hit.index].material)];
      if (isSolidTexture(m.texture.kind)) {
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(g[c] - hit.tc.solid[c]));
      } else {
        worst = std::max(worst, coordinateDistance(g[0], hit.tc.uv.x));
        worst = std::max(worst, coordinateDistance(g[1], hit.tc.uv.y));
      }
    }
    EXPECT_EQ(wrongKind, 0);
    EXPECT_GT(checked[HIT_PLANE], w * h / 5);
    EXPECT_GT(checked[HIT_SPHERE], w * h / 10);
    EXPECT_GT(checked[HIT_NONE], 0);
    EXPECT_LT(worst, 1e-3) << "largest texture-coordinate difference";
  }
}

class AlbedoTest : public RenderTest, public ::testing::WithParamInterface<const char*> {};

// The kernel's texture colour (OUTPUT_ALBEDO) equals the CPU double evaluation of the
// same texture at the reference hit, for every course material on the sphere and the
// checker on the plane: checks parity, noise, marble, wood, turbulence, image lookups.
TEST_P(AlbedoTest, TextureColourMatchesDoubleReference) {
  const std::string material = GetParam();
  const int w = 128, h = 96;
  Scene scene = courseScene(material);
  std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);
  std::vector<PixelRef> ref = referenceImage(scene, w, h);
  ImageRGBA8 image;
  if (material == "anImage") {
    const Material& m = scene.materials[size_t(scene.spheres[0].material)];
    ASSERT_NO_THROW(image = loadImage(m.texture.imagePath));
  }

  int checked = 0, mismatches = 0;
  double worst = 0.0;
  for (int i = 0; i < w * h; ++i) {
    const ReferenceHit& hit = ref[i].hit;
    if (!ref[i].reliable || hit.kind == HIT_NONE) continue;
    const Material& m = scene.materials[size_t(hit.kind == HIT_PLANE ? scene.planes[hit.index].material
                                                                      : scene.spheres[hit.index].material)];
    glm::dvec3 expected;
    double tolerance = 2e-3;
    if (m.texture.kind == TextureKind::Image) {
      expected = sampleImageReference(image, hit.tc);
      tolerance = 0.02;  // 8-bit texels, driver filtering precision
    } else {
      // Skip pixels within float rounding of a discontinuity (check edges, wood rings).
      double blend = textureBlendReference(m.texture, hit.tc);
      const double eps = 1e-4;
      auto nearEdge = [&](double x) { return std::abs(x - std::round(x)) < eps * std::max(1.0, std::abs(x)); };
      bool discontinuous = false;
      if (m.texture.kind == TextureKind::Checker) {
        double sq = std::max(std::round(double(m.texture.squares)), 1.0);
        discontinuous = nearEdge((hit.tc.uv.x + hit.tc.tile.x) * sq) || nearEdge((hit.tc.uv.y + hit.tc.tile.y) * sq) ||
                        nearEdge(hit.tc.uv.x * sq) || nearEdge(hit.tc.uv.y * sq);
      } else if (m.texture.kind == TextureKind::SolidChecker) {
        for (int c = 0; c < 3; ++c) discontinuous |= nearEdge(hit.tc.solid[c] * double(m.texture.squares));
      } else if (m.texture.kind == TextureKind::Wood) {
        discontinuous = blend < 1e-2 || blend > 1.0 - 1e-2;
      }
      if (discontinuous) continue;
      expected = textureColorReference(m.texture, hit.tc);
    }
    ++checked;
    const float* g = &gpu[size_t(i) * 4];
    double err = 0.0;
    for (int c = 0; c < 3; ++c) err = std::max(err, std::abs(double(g[c]) - expected[c]));
    worst = std::max(worst, err);
    if (err > tolerance) ++mismatches;
  }
  EXPECT_GT(checked, w * h / 3);
  EXPECT_EQ(mismatches, 0) << material << ": worst channel difference " << worst;
}

INSTANTIATE_TEST_SUITE_P(Materials, AlbedoTest, ::testing::ValuesIn(kMaterials),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

// The shaded image is not black, the sphere shades, the plane shows a shadow.
TEST_F(RenderTest, DefaultSceneHasShadowOnPlane) {
  Scene scene = parseSceneFile(courseScenePath());
  ASSERT_FALSE(scene.lights.empty());
  const int w = 160, h = 120;
  std::vector<float> shaded = render(scene, w, h, OUTPUT_SHADED);
  std::vector<float> albedo = render(scene, w, h, OUTPUT_ALBEDO);
  std::vector<PixelRef> ref = referenceImage(scene, w, h);
  const glm::dvec3 light(scene.lights[0].position);
  const Sphere& sphere = scene.spheres[0];
  int shadowed = 0, lit = 0, wrong = 0;
  for (int i = 0; i < w * h; ++i) {
    const ReferenceHit& hit = ref[i].hit;
    if (!ref[i].reliable || hit.kind != HIT_PLANE) continue;
    // Does the segment from the plane point to the light pass through the sphere?
    glm::dvec3 toLight = light - hit.p;
    double dist = glm::length(toLight);
    glm::dvec3 l = toLight / dist;
    glm::dvec3 f = hit.p - glm::dvec3(sphere.center);
    double b = glm::dot(f, l);
    double perp = std::sqrt(std::max(glm::dot(f, f) - b * b, 0.0));
    if (std::abs(perp - sphere.radius) < 0.05) continue;  // penumbra-free edge: skip
    bool inShadow = perp < sphere.radius && b < 0.0;
    // In shadow only the ambient term is left: shaded = ambient_light * k_a * albedo.
    const Material& m = scene.materials[size_t(scene.planes[hit.index].material)];
    double ambientOnly = double(scene.ambientLight.x) * m.ambient.x;
    double ratio = double(shaded[i * 4]) / std::max(1e-4, double(albedo[i * 4]));
    bool looksShadowed = std::abs(ratio - ambientOnly) < 1e-3;
    (inShadow ? shadowed : lit)++;
    if (inShadow != looksShadowed) ++wrong;
  }
  EXPECT_GT(shadowed, 50);
  EXPECT_GT(lit, 500);
  EXPECT_EQ(wrong, 0);
}

// An image over the device's storage-buffer range is rendered in bands of rows (headless.cpp):
// bands of 7 rows, the last one shorter, give the whole image's floats bit for bit, with 2 x 2
// samples so that sub-pixel positions cross the band edges too.
TEST_F(RenderTest, BandsRenderTheWholeImage) {
  Scene scene = parseSceneFile(courseScenePath());
  const uint32_t w = 64, h = 50, rows = 7;
  std::vector<float> whole = render(scene, w, h, OUTPUT_SHADED, 2);
  ASSERT_EQ(bandCount(*renderer_), 1u);
  renderer_->bandRows = rows;  // as the output buffer held only 7 rows (it holds all 50)
  EXPECT_EQ(bandCount(*renderer_), 8u);
  std::vector<float> banded(whole.size(), -1.0f);
  for (uint32_t first = 0; first < h; first += rows) {
    selectBand(*renderer_, first);
    renderFrame(*renderer_);
    readbackFrame(*renderer_);
    const float* band = framePixels(*renderer_);
    std::copy(band, band + size_t(w) * bandHeight(*renderer_) * 4, banded.begin() + ptrdiff_t(size_t(first) * w * 4));
  }
  EXPECT_EQ(bandHeight(*renderer_), h % rows);
  EXPECT_EQ(banded, whole);
  renderer_->bandRows = h;
  selectBand(*renderer_, 0);
}

// The suite's zero-error check covers synchronization too: two writes to one buffer with no
// barrier between them are a write-after-write hazard, which the layer must report.
TEST_F(RenderTest, SynchronizationValidationReportsAHazard) {
  const Device& device = renderer_->device;
  Buffer buffer = createBuffer(device, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  VkCommandBuffer cmd = beginCommands(device);
  vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 1u);
  vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 2u);
  submitAndWait(device, cmd);
  destroyBuffer(device, buffer);
  EXPECT_GT(renderer_->device.validationErrors, errorsBefore_);
  errorsBefore_ = renderer_->device.validationErrors;  // expected: not a failure of the suite
}

}  // namespace
