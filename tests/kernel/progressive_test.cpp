// Progressive rendering (the viewer): N x N samples added one per dispatch must end
// bit-identical to the single dispatch that loops over them, for point and box filtering;
// the means on the way are the means of the samples so far.
#include "support/course_scene.h"
#include "support/gpu_fixture.h"
#include "gpu_scene.h"
#include "parser.h"
#include "renderer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

class ProgressiveTest : public RenderTest {
 protected:
  static constexpr uint32_t kWidth = 96, kHeight = 72;

  // Accumulates the N x N samples one dispatch each; `means` gets the image after each.
  std::vector<float> renderProgressive(const Scene& scene, uint32_t n, uint32_t filter,
                                       std::vector<std::vector<float>>* means = nullptr) {
    renderer_->accumulate = true;
    GpuScene gpuScene = buildGpuScene(scene, kWidth, kHeight);
    uploadScene(*renderer_, gpuScene);
    KernelOptions kernel;
    kernel.textureFilter = filter;
    kernel.samplesPerSide = n;
    kernel.progressive = true;
    preparePipeline(*renderer_, kernelKey(gpuScene, kernel));
    std::vector<float> image;
    for (uint32_t i = 0; i < n * n; ++i) {
      renderSample(*renderer_, i);
      readbackFrame(*renderer_);
      const float* pixels = framePixels(*renderer_);
      image.assign(pixels, pixels + size_t(kWidth) * kHeight * 4);
      if (means) means->push_back(image);
    }
    renderer_->accumulate = false;
    return image;
  }
};

struct Case {
  const char* material;
  uint32_t samplesPerSide, filter;
};

class ProgressiveEqualsLoop : public ProgressiveTest, public ::testing::WithParamInterface<Case> {};

TEST_P(ProgressiveEqualsLoop, BitIdentical) {
  const Case c = GetParam();
  Scene scene = courseScene(c.material);
  std::vector<float> loop = render(scene, kWidth, kHeight, OUTPUT_SHADED, c.samplesPerSide, c.filter);
  std::vector<float> progressive = renderProgressive(scene, c.samplesPerSide, c.filter);
  ASSERT_EQ(loop.size(), progressive.size());
  size_t differing = 0;
  for (size_t i = 0; i < loop.size(); ++i) differing += std::memcmp(&loop[i], &progressive[i], sizeof(float)) != 0;
  EXPECT_EQ(differing, 0u) << c.material << ", " << c.samplesPerSide << "x" << c.samplesPerSide
                           << " samples, filter " << c.filter;
  EXPECT_EQ(countNonFinite(progressive), 0u);
}

INSTANTIATE_TEST_SUITE_P(Kinds, ProgressiveEqualsLoop,
                         ::testing::Values(Case{"aSolidChecker", 1, FILTER_POINT}, Case{"aSolidChecker", 2, FILTER_POINT},
                                           Case{"aSolidChecker", 3, FILTER_POINT}, Case{"aMarble", 4, FILTER_POINT},
                                           Case{"anImage", 3, FILTER_POINT}, Case{"aSolidChecker", 3, FILTER_BOX},
                                           Case{"aTurbulence", 2, FILTER_BOX}, Case{"anImage", 2, FILTER_BOX}),
                         // Named by the case (aMarble_4x4_point), not by its bytes: the default
                         // name prints the material pointer, which changes from build to build.
                         [](const ::testing::TestParamInfo<Case>& info) {
                           const Case& c = info.param;
                           return std::string(c.material) + "_" + std::to_string(c.samplesPerSide) + "x" +
                                  std::to_string(c.samplesPerSide) + (c.filter == FILTER_BOX ? "_box" : "_point");
                         });

// The mean after k samples is the mean of the first k samples: the first image is the one
// sample at the centre of the top-left cell, and restarting at sample 0 forgets the old sums.
TEST_F(ProgressiveTest, MeansOfTheSamplesSoFar) {
  Scene scene = courseScene("aMarble");
  std::vector<std::vector<float>> means;
  renderProgressive(scene, 2, FILTER_POINT, &means);
  ASSERT_EQ(means.size(), 4u);
  // Sample 0 alone: the 1-sample-per-pixel image with the camera ray through (x + 1/4, y + 1/4),
  // which differs from the pixel centre's image on edges.
  std::vector<float> centre = render(scene, kWidth, kHeight, OUTPUT_SHADED, 1, FILTER_POINT);
  size_t edgePixels = 0;
  for (size_t i = 0; i < centre.size(); ++i) edgePixels += centre[i] != means[0][i];
  EXPECT_GT(edgePixels, 0u) << "the first sample is not off the pixel centre";
  // mean_k * (k + 1) - mean_{k-1} * k recovers sample k: within float rounding of [0, 1].
  for (size_t k = 1; k < means.size(); ++k) {
    double worst = 0.0;
    for (size_t i = 0; i < centre.size(); ++i) {
      double sample = double(means[k][i]) * double(k + 1) - double(means[k - 1][i]) * double(k);
      worst = std::max(worst, std::max(-sample, sample - 4.0));  // well above this scene's brightest radiance
    }
    EXPECT_LT(worst, 1e-5) << "sample " << k << " is not a radiance: the sums are wrong";
  }
  // Restart: a second accumulation ends where the first did.
  std::vector<float> again = renderProgressive(scene, 2, FILTER_POINT);
  EXPECT_EQ(std::memcmp(again.data(), means.back().data(), again.size() * sizeof(float)), 0);
}

}  // namespace
