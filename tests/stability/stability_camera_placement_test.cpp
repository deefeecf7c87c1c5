// Stability: the eye where intersection formulas turn singular. Inside
// a sphere (only the far root is in front), and on a plane or just above it looking parallel
// to it (t = 0/0 or -inf): hit/miss and coordinates equal the reference's.
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

// --- 3. camera inside the sphere ---------------------------------------------

// Camera at the centre of a textured sphere of radius 5 (and off-centre, still inside),
// looking towards the u seam, a light inside: every pixel hits the sphere (its far root),
// the coordinates equal the reference's, and no pixel is dark: from inside, every point
// of the sphere sees a light that is inside it (N.L >= (5 - 1.3) / 6.3 > 0.5 with the
// normal flipped to face the eye), so no pixel may look shadowed.
TEST_F(StabilityTest, CameraInsideSphereSeesItEverywhere) {
  const int w = 64, h = 48;
  const glm::vec3 eyes[] = {{0, 0, 0}, {1.5f, -2.0f, 0.5f}};
  const TextureKind kinds[] = {TextureKind::Checker, TextureKind::SolidChecker};
  std::vector<Scene> scenes;
  for (TextureKind kind : kinds)
    for (const glm::vec3& eye : eyes) scenes.push_back(insideScene(eye, kind));
  std::vector<Images> images = renderEach(scenes, w, h, {OUTPUT_COORDS, OUTPUT_SHADED, OUTPUT_ALBEDO});
  for (size_t k = 0; k < scenes.size(); ++k) {
    const TextureKind kind = kinds[k / 2];
    SCOPED_TRACE(std::string(textureKindName(kind)) + (k % 2 == 0 ? " at the centre" : " off-centre"));
    const Scene& scene = scenes[k];
    const std::vector<float>& coords = images[k].coords;
    const std::vector<float>& shaded = images[k].shaded;
    const std::vector<float>& albedo = images[k].albedo;
    std::vector<ReferenceHit> ref = referenceHits(scene, w, h);

    int notSphere = 0, shadowed = 0, checked = 0;
    double worst = 0.0, sum = 0.0;
    for (size_t i = 0; i < ref.size(); ++i) {
      if (gpuKind(coords, i) != HIT_SPHERE) ++notSphere;
      if (ref[i].kind != HIT_SPHERE) ++notSphere;
      if (looksShadowed(&shaded[i * 4], &albedo[i * 4], 0.1)) ++shadowed;
      sum += (shaded[i * 4] + shaded[i * 4 + 1] + shaded[i * 4 + 2]) / 3.0;
      if (ref[i].kind != HIT_SPHERE || std::abs(ref[i].n.y) > 0.999) continue;
      ++checked;
      worst = std::max(worst, coordError(scene, ref[i], &coords[i * 4]));
    }
    EXPECT_EQ(notSphere, 0);
    EXPECT_EQ(shadowed, 0);
    EXPECT_GT(checked, w * h * 9 / 10);
    EXPECT_LT(worst, 1e-3);
    // Checker colours average ~0.5, lit by N.L > 0.5 plus ambient: the mean is > 0.25.
    double mean = sum / (w * h);
    EXPECT_GT(mean, 0.25);
    std::cout << "[inside] " << textureKindName(kind) << ": worst coordinate error " << worst
              << ", mean shaded " << mean << "\n";
  }
}

// --- 4. camera on the plane, parallel rays -----------------------------------

// The eye on the plane y = 0 (and 1e-3 above it) looking horizontally; the image height is
// odd so the middle row's rays have d_y = 0 exactly: t = 0/0 (NaN) on the plane, -inf just
// above it. Those rays, and every ray from an eye on the plane (t = +-0), must miss:
// hit/miss per pixel equals the double reference's (which skips d.n == 0 and t <= 0).
TEST_F(StabilityTest, CameraOnPlaneParallelRaysMiss) {
  const int w = 64, h = 49;
  const float heights[] = {0.0f, 1e-3f};
  std::vector<Scene> scenes = {onPlaneScene(heights[0]), onPlaneScene(heights[1])};
  std::vector<Images> images = renderEach(scenes, w, h, {OUTPUT_COORDS, OUTPUT_SHADED});
  for (size_t k = 0; k < scenes.size(); ++k) {
    const float height = heights[k];
    SCOPED_TRACE("eye height " + fmtG(height));
    const Scene& scene = scenes[k];
    const std::vector<float>& coords = images[k].coords;
    const std::vector<float>& shaded = images[k].shaded;
    std::vector<ReferenceHit> ref = referenceHits(scene, w, h);

    int wrong = 0, skipped = 0, planeHits = 0, sphereHits = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
      if (ref[i].edgeMargin < 2e-3) {  // sphere silhouette
        ++skipped;
        continue;
      }
      if (gpuKind(coords, i) != ref[i].kind) ++wrong;
      planeHits += gpuKind(coords, i) == HIT_PLANE;
      sphereHits += gpuKind(coords, i) == HIT_SPHERE;
    }
    std::cout << "[eye on plane] height " << fmtG(height) << ": " << wrong << " wrong hit/miss, " << planeHits
              << " plane and " << sphereHits << " sphere pixels, " << skipped
              << " skipped at the silhouette\n";
    EXPECT_EQ(wrong, 0);
    EXPECT_LT(skipped, w);
    EXPECT_GT(sphereHits, 50);
    if (height == 0.0f)
      EXPECT_EQ(planeHits, 0);  // every ray from a point on the plane has t = +-0 or NaN
    else
      EXPECT_GT(planeHits, w * (h / 2 - 1));
    // The horizon row: nothing but the sphere and the background colour.
    int horizonBackground = 0;
    for (int x = 0; x < w; ++x) {
      size_t i = size_t(h / 2) * w + x;
      int kind = gpuKind(coords, i);
      EXPECT_NE(kind, HIT_PLANE) << "horizon pixel " << x;
      if (kind == HIT_NONE) {
        ++horizonBackground;
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(shaded[i * 4 + c], scene.background[c]) << "horizon pixel " << x;
      }
    }
    EXPECT_GT(horizonBackground, w / 2);
  }
}

}  // namespace
