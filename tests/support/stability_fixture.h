// The fixture and per-pixel checks of the stability suite (tests/stability_*_test.cpp): the
// device fixture of support/gpu_fixture.h with every image checked for NaN/inf in the float
// buffer, before any quantisation (an 8-bit conversion of NaN is undefined and may hide it).
#pragma once

#include "reference.h"
#include "texture.h"

#include "support/gpu_fixture.h"
#include "support/reference_pixels.h"
#include "support/stability_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

inline const char* modeName(uint32_t mode) {
  return mode == OUTPUT_COORDS ? "coords" : mode == OUTPUT_ALBEDO ? "albedo" : "shaded";
}

inline const Material& materialOf(const Scene& scene, const ReferenceHit& hit) {
  int m = hit.kind == HIT_PLANE ? scene.planes[size_t(hit.index)].material
                                : scene.spheres[size_t(hit.index)].material;
  return scene.materials[size_t(m)];
}

// What the primary ray hit (HIT_*), from the alpha of a debug output.
inline int gpuKind(const std::vector<float>& debug, size_t i) { return int(debug[i * 4 + 3]); }

// Largest difference between the kernel's OUTPUT_COORDS and the reference's coordinate
// at a pixel: uv for the 2D kinds, the solid coordinate otherwise.
inline double coordError(const Scene& scene, const ReferenceHit& hit, const float* g) {
  const Material& m = materialOf(scene, hit);
  double worst = 0.0;
  if (isSolidTexture(m.texture.kind) || m.texture.kind == TextureKind::None) {
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(g[c]) - hit.tc.solid[c]));
  } else {
    worst = std::max(worst, coordinateDistance(g[0], hit.tc.uv.x));
    worst = std::max(worst, coordinateDistance(g[1], hit.tc.uv.y));
  }
  return worst;
}

// In shadow (or facing away from every light) only the ambient term is left, which for a
// textured material is ambient_light * k_a * albedo exactly (shaders/shading.glsl). A lit
// pixel adds at least light * albedo * N.L, which for N.L > 0.05 and albedo >= 0.1 is
// >= 5e-3, fifty times the 1e-4 allowed for float rounding of the ambient product.
inline bool looksShadowed(const float* shaded, const float* albedo, double ambientTimesKa) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(double(shaded[c]) - ambientTimesKa * albedo[c]) > 1e-4) return false;
  return true;
}

// The outputs of one scene (empty where not rendered).
struct Images {
  std::vector<float> coords, shaded, albedo;
};

// The device fixture of support/gpu_fixture.h (one Renderer per suite, validation on, no new
// validation error per test); every image it renders is checked for NaN/inf here.
class StabilityTest : public RenderTest {
 protected:
  std::vector<float> render(const Scene& scene, uint32_t width, uint32_t height, uint32_t mode,
                            uint32_t samplesPerSide = 1, uint32_t filter = 0) {
    std::vector<float> out = RenderTest::render(scene, width, height, mode, samplesPerSide, filter);
    EXPECT_EQ(countNonFinite(out), 0u) << "NaN/inf floats in the " << modeName(mode) << " image ("
                                       << samplesPerSide << "x" << samplesPerSide << " samples, filter "
                                       << filter << ")";
    return out;
  }

  // Every scene in each of `modes`, mode by mode: scenes with the same texture kinds then
  // share one pipeline (a new specialisation is a compile on lavapipe, ~0.3 s).
  std::vector<Images> renderEach(const std::vector<Scene>& scenes, uint32_t width, uint32_t height,
                                 std::initializer_list<uint32_t> modes) {
    std::vector<Images> images(scenes.size());
    for (uint32_t mode : modes) {
      for (size_t k = 0; k < scenes.size(); ++k) {
        SCOPED_TRACE("scene " + std::to_string(k));
        std::vector<float>& out = mode == OUTPUT_COORDS   ? images[k].coords
                                  : mode == OUTPUT_ALBEDO ? images[k].albedo
                                                          : images[k].shaded;
        out = render(scenes[k], width, height, mode);
      }
    }
    return images;
  }
};
