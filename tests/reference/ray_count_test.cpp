// `raytex bench`'s ray count against counts worked out from the geometry (no device).
#include "parser.h"
#include "ray_count.h"
#include "reference.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

// A level camera at height eyeY over the floor y = 0 (below it for eyeY < 0): the rays
// towards the floor, those through the lower half of the image (the upper half from below;
// an even height puts no sample on the horizon), hit it.
std::string floorScene(int eyeY, const std::string& lights) {
  const std::string y = std::to_string(eyeY);
  return "material m { diffuse = (0.5, 0.5, 0.5); }\n"
         "camera { eye = (0, " + y + ", 0); lookat = (0, " + y + ", -1); up = (0, 1, 0); fov = 60; }\n" +
         lights + "plane { normal = (0, 1, 0); distance = 0; m; }\n";
}

TEST(RayCount, FloorBelowTheHorizonCastsOneShadowRayPerSampleAndLightAbove) {
  Scene scene = parseSceneText(floorScene(1, "light { position = (3, 10, -4); color = (1, 1, 1); }\n"
                                             "light { position = (-2, 4, 1); color = (1, 1, 1); }\n"),
                               "horizon.cfg");
  RayCount one = countRays(scene, 16, 10, 1);
  EXPECT_EQ(one.primary, 16u * 10u);
  EXPECT_EQ(one.shadow, 2u * 16u * 5u);  // two lights, five rows
  // 3 x 3 samples: the sub-rows of the upper five rows all lie above the horizon.
  RayCount nine = countRays(scene, 16, 10, 3);
  EXPECT_EQ(nine.primary, 16u * 10u * 9u);
  EXPECT_EQ(nine.shadow, 2u * 16u * 5u * 9u);
}

TEST(RayCount, LightBelowTheFloorCastsNone) {
  Scene scene = parseSceneText(floorScene(1, "light { position = (0, -3, -5); color = (1, 1, 1); }\n"),
                               "below.cfg");
  RayCount count = countRays(scene, 16, 10, 2);
  EXPECT_EQ(count.primary, 16u * 10u * 4u);
  EXPECT_EQ(count.shadow, 0u);
}

// Seen from below, the floor's normal turns to face the eye: a light below it is in front.
TEST(RayCount, FloorSeenFromBelowIsLitFromBelow) {
  Scene scene = parseSceneText(floorScene(-1, "light { position = (1, -6, -2); color = (1, 1, 1); }\n"
                                              "light { position = (-4, -2, 3); color = (1, 1, 1); }\n"
                                              "light { position = (0, 5, -3); color = (1, 1, 1); }\n"),
                               "underside.cfg");
  RayCount count = countRays(scene, 16, 10, 1);
  EXPECT_EQ(count.shadow, 2u * 16u * 5u);  // the upper five rows, the two lights below
}

TEST(RayCount, EmptySceneHasOnlyPrimaryRays) {
  Scene scene = parseSceneText(
      "camera { eye = (0, 0, 5); lookat = (0, 0, 0); up = (0, 1, 0); fov = 40; }\n"
      "light { position = (0, 0, 10); color = (1, 1, 1); }\n",
      "empty.cfg");
  RayCount count = countRays(scene, 7, 5, 2);
  EXPECT_EQ(count.primary, 7u * 5u * 4u);
  EXPECT_EQ(count.shadow, 0u);
}

// A sphere lit from the eye: every point the eye sees faces the light, so every sample that
// hits casts one shadow ray. A sample hits when its ray is within asin(r / D) of the direction
// to the centre, D the eye's distance to it: counted here from the rays' angles alone.
TEST(RayCount, SphereLitFromTheEyeCastsOneShadowRayPerSampleOnItsDisc) {
  Scene scene = parseSceneText(
      "material m { diffuse = (0.5, 0.5, 0.5); }\n"
      "camera { eye = (0.3, 0.2, 6); lookat = (0, 0, 0); up = (0, 1, 0); fov = 35; }\n"
      "light { position = (0.3, 0.2, 6); color = (1, 1, 1); }\n"
      "sphere { center = (0.4, -0.1, 0); radius = 1.5; m; }\n",
      "disc.cfg");
  const int width = 41, height = 29, n = 2;
  const glm::dvec3 eye(scene.camera.eye), centre(scene.spheres[0].center);
  const double cosLimit = std::cos(std::asin(double(scene.spheres[0].radius) / glm::length(centre - eye)));
  const glm::dvec3 toCentre = glm::normalize(centre - eye);
  const ReferenceCamera camera = referenceCamera(scene.camera, width, height);
  uint64_t expected = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int k = 0; k < n * n; ++k) {
        const double cosAngle =
            glm::dot(referenceRayDirection(camera, x, y, (k % n + 0.5) / n - 0.5, (k / n + 0.5) / n - 0.5),
                     toCentre);
        ASSERT_GT(std::abs(cosAngle - cosLimit), 1e-9) << "a sample grazes the silhouette";
        if (cosAngle > cosLimit) ++expected;
      }
  ASSERT_GT(expected, uint64_t(width * height));  // the disc covers a good part of the image
  ASSERT_LT(expected, uint64_t(width * height * n * n));
  RayCount count = countRays(scene, width, height, n);
  EXPECT_EQ(count.primary, uint64_t(width) * height * n * n);
  EXPECT_EQ(count.shadow, expected);
}

}  // namespace
