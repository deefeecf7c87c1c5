// Stability: self-shadowing. A light at a grazing angle over a sphere on a
// plane, at scale 1 and 1e4: no acne on the lit side, no light leaking into the shadow.
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

// --- 6. self-shadowing and acne -------------------------------------------------

// A point light at a grazing angle (1.2 units up, ~9 away) over a sphere resting on a
// plane, at scale 1 and with everything (camera, light, sizes, tex_scale) times 1e4. No
// lit-side pixel (N.L > 0.05 by the reference, outside the analytic shadow of the sphere
// by more than 2 % of its radius) may render shadowed; and no pixel inside that shadow may
// render lit. (The sphere cannot shadow itself where N.L > 0; the plane lies below both
// ends of every shadow ray.) Measured at both scales: 4652 lit pixels (124 on the sphere),
// 699 in shadow, 0 wrong either way.
TEST_F(StabilityTest, GrazingLightCastsNoAcne) {
  const int w = 96, h = 72;
  const float scales[] = {1.0f, 1e4f};
  std::vector<Scene> scenes = {acneScene(scales[0]), acneScene(scales[1])};
  std::vector<Images> images = renderEach(scenes, w, h, {OUTPUT_SHADED, OUTPUT_ALBEDO});
  for (size_t k = 0; k < scenes.size(); ++k) {
    const float scale = scales[k];
    SCOPED_TRACE("scale " + fmtG(scale));
    const Scene& scene = scenes[k];
    const std::vector<float>& shaded = images[k].shaded;
    const std::vector<float>& albedo = images[k].albedo;
    std::vector<ReferenceHit> ref = referenceHits(scene, w, h);

    const glm::dvec3 light(scene.lights[0].position);
    const glm::dvec3 center(scene.spheres[0].center);
    const double radius = scene.spheres[0].radius;
    int lit = 0, shadowed = 0, litLooksShadowed = 0, shadowLooksLit = 0, sphereLit = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
      const ReferenceHit& hit = ref[i];
      if (hit.kind == HIT_NONE || hit.edgeMargin < 2e-3) continue;
      glm::dvec3 toLight = light - hit.p;
      double dist = glm::length(toLight);
      glm::dvec3 l = toLight / dist;
      bool inShadow = false;
      if (hit.kind == HIT_PLANE) {
        // Closest approach of the segment p -> light to the sphere's centre.
        double s = std::clamp(glm::dot(center - hit.p, l), 0.0, dist);
        double miss = glm::length(hit.p + s * l - center);
        if (std::abs(miss - radius) < 0.02 * radius) continue;
        inShadow = miss < radius;
      }
      bool dark = looksShadowed(&shaded[i * 4], &albedo[i * 4], 0.1);
      if (inShadow) {
        ++shadowed;
        shadowLooksLit += !dark;
      } else if (glm::dot(hit.n, l) > 0.05) {
        ++lit;
        sphereLit += hit.kind == HIT_SPHERE;
        litLooksShadowed += dark;
      }
    }
    std::cout << "[acne] scale " << scale << ": " << lit << " lit (" << sphereLit << " on the sphere), "
              << shadowed << " in shadow; " << litLooksShadowed << " lit pixels shadowed, " << shadowLooksLit
              << " shadow pixels lit\n";
    EXPECT_GT(lit, w * h / 4);
    EXPECT_GT(sphereLit, 100);
    EXPECT_GT(shadowed, 100);
    EXPECT_EQ(litLooksShadowed, 0);
    EXPECT_EQ(shadowLooksLit, 0);
  }
}

}  // namespace
