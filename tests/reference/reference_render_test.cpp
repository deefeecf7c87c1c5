// The float64 reference renderer against values worked out by hand (no device).
#include "parser.h"
#include "reference_render.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// Camera on +z looking at a unit sphere; one light behind the camera on the view axis.
// At the centre pixel N = L = V = +z, so N.L = 1 and R.V = 1:
//   colour = ambient_light*k_a + k_d + k_s   (untextured, white light).
TEST(ReferenceRender, CentrePixelIsHandComputedPhong) {
  Scene scene = parseSceneText(
      "material m { ambient = (0.1, 0.2, 0.3); diffuse = (0.5, 0.25, 0.125); specular = (0.25, 0.25, 0.25);"
      " shininess = 7; }\n"
      "camera { eye = (0, 0, 5); lookat = (0, 0, 0); up = (0, 1, 0); fov = 30; }\n"
      "light { position = (0, 0, 10); color = (1, 1, 1); }\n"
      "ambient_light = (0.5, 0.5, 0.5);\n"
      "background = (0.01, 0.02, 0.03);\n"
      "sphere { center = (0, 0, 0); radius = 1; m; }\n",
      "phong.cfg");
  ReferenceImage img = renderReference(scene, 9, 9, 1, 1);  // odd size: a pixel centre on the axis
  // The scene stores its values as float (0.1f...): 1e-7 covers that rounding, nothing more.
  const double* centre = &img.rgb[(4 * 9 + 4) * 3];
  EXPECT_NEAR(centre[0], 0.5 * 0.1 + 0.5 + 0.25, 1e-7);
  EXPECT_NEAR(centre[1], 0.5 * 0.2 + 0.25 + 0.25, 1e-7);
  EXPECT_NEAR(centre[2], 0.5 * 0.3 + 0.125 + 0.25, 1e-7);
  const double* corner = &img.rgb[0];  // misses the sphere
  EXPECT_DOUBLE_EQ(corner[0], 0.01f);
  EXPECT_DOUBLE_EQ(corner[2], 0.03f);
  EXPECT_EQ(img.nonFinite, 0u);
}

// A light hidden behind an occluder leaves only the ambient term.
TEST(ReferenceRender, ShadowLeavesTheAmbientTerm) {
  Scene scene = parseSceneText(
      "material m { ambient = (0.2, 0.2, 0.2); diffuse = (0.8, 0.8, 0.8); specular = (0, 0, 0); }\n"
      "camera { eye = (0, 5, 0.001); lookat = (0, 0, 0); up = (0, 0, -1); fov = 10; }\n"
      "light { position = (0, 20, 0); color = (1, 1, 1); }\n"
      "sphere { center = (0, 10, 0); radius = 1; m; }\n"  // between the light and the floor, behind the camera
      "plane { normal = (0, 1, 0); distance = 0; m; }\n",
      "shadow.cfg");
  ReferenceImage img = renderReference(scene, 5, 5, 1, 1);
  const double* centre = &img.rgb[(2 * 5 + 2) * 3];
  EXPECT_NEAR(centre[0], 0.2, 1e-7);  // ambient_light (1) * k_a (0.2f)
}

// Box-filtered stratified samples: a camera looking horizontally puts the horizon through
// the centre of a 1x1 image. With 8x8 samples exactly the lower four rows of samples hit the
// white floor (ambient only) and the upper four the black sky: 0.5. With one sample the
// centre ray is parallel to the floor: a miss, 0.
TEST(ReferenceRender, StratifiedSamplesAverageWithABoxFilter) {
  Scene scene = parseSceneText(
      "material w { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0); }\n"
      "camera { eye = (0, 0.5, 10); lookat = (0, 0.5, 0); up = (0, 1, 0); fov = 20; }\n"
      "ambient_light = (1, 1, 1);\n"
      "background = (0, 0, 0);\n"
      "plane { normal = (0, 1, 0); distance = 0; w; }\n",
      "box.cfg");
  EXPECT_DOUBLE_EQ(renderReference(scene, 1, 1, 1, 1).rgb[0], 0.0);
  EXPECT_DOUBLE_EQ(renderReference(scene, 1, 1, 8, 1).rgb[0], 0.5);
}

}  // namespace
