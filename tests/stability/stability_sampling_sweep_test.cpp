// Stability: every scene of the suite (support/stability_scenes.h) again, with stratified
// samples off the pixel centres and box-filtered textures (ray differentials parallel to a
// plane, infinite du/dp at a pole, zero-size spheres): finite, and only averaging.
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

// --- 9. every scene again, supersampled and filtered --------------------------------------

// The shaded images of every scene above, 65 x 49, at 1 sample per pixel, with 2 x 2
// stratified samples (rays off the pixel centres), and, where the kernel has it, with
// box-filtered textures (ray differentials: differential rays parallel to a plane, du/dp
// infinite at a pole, zero-size spheres): all finite. Supersampling and filtering only
// average, so each image's mean must stay within 0.05 of the point-sampled one (measured:
// at most 0.014).
TEST_F(StabilityTest, AllScenesFiniteWhenSupersampledAndFiltered) {
  const int w = 65, h = 49;
  std::vector<NamedScene> scenes = {
      {"checker floor", checkerFloorScene()},
      {"pole, image", poleScene(TextureKind::Image)},
      {"pole, noise", poleScene(TextureKind::Noise)},
      {"pole, solid checker", poleScene(TextureKind::SolidChecker)},
      {"inside, checker", insideScene({0, 0, 0}, TextureKind::Checker)},
      {"inside off-centre, solid checker", insideScene({1.5f, -2.0f, 0.5f}, TextureKind::SolidChecker)},
      {"eye on the plane", onPlaneScene(0.0f)},
      {"eye 1e-3 above the plane", onPlaneScene(1e-3f)},
      {"small far sphere", smallSphereScene(0.1, 1000.0)},
      {"acne, scale 1", acneScene(1.0f)},
      {"acne, scale 1e4", acneScene(1e4f)},
      {"far, 1e4", farScene(1e4)},
      {"far, 1e6", farScene(1e6)},
  };
  for (NamedScene& s : degenerateScenes()) scenes.push_back(std::move(s));
  // Scenes with the same texture kinds share a pipeline: render them together.
  std::stable_sort(scenes.begin(), scenes.end(), [](const NamedScene& a, const NamedScene& b) {
    return sceneShape(a.scene).kinds() < sceneShape(b.scene).kinds();
  });

  struct Config {
    const char* name;
    uint32_t samplesPerSide, filter;
  };
  std::vector<Config> configs = {{"2x2 samples", 2, 0}};
#ifdef FILTER_BOX
  configs.push_back({"box filter", 1, FILTER_BOX});
  configs.push_back({"box filter, 2x2 samples", 2, FILTER_BOX});
#endif
  auto mean = [](const std::vector<float>& image) {
    double sum = 0.0;
    for (size_t i = 0; i < image.size(); i += 4) sum += image[i] + image[i + 1] + image[i + 2];
    return sum / double(image.size() / 4 * 3);
  };
  std::vector<double> pointMeans;
  for (const NamedScene& s : scenes) {
    SCOPED_TRACE(s.name);
    pointMeans.push_back(mean(render(s.scene, w, h, OUTPUT_SHADED)));
  }
  double worst = 0.0;
  for (const Config& config : configs) {
    for (size_t k = 0; k < scenes.size(); ++k) {
      SCOPED_TRACE(scenes[k].name + ", " + config.name);
      double m = mean(render(scenes[k].scene, w, h, OUTPUT_SHADED, config.samplesPerSide, config.filter));
      EXPECT_NEAR(m, pointMeans[k], 0.05);
      worst = std::max(worst, std::abs(m - pointMeans[k]));
    }
  }
  std::cout << "[sweep] " << scenes.size() << " scenes x " << configs.size() + 1
            << " configurations; largest change of an image mean " << fmtG(worst) << "\n";
}

}  // namespace
