// Stability: values at the ends of the float range. Texture scales,
// check counts, sphere sizes and positions and colours near 3e38 or 1e-38: coordinates,
// phases and shading clamp instead of overflowing, and the double reference agrees.
#include "reference.h"
#include "reference_render.h"
#include "scene_limits.h"
#include "texture.h"
#include "texture_kinds.h"

#include "support/stability_fixture.h"
#include "support/reference_rmse.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace {

// --- 10. extreme accepted values ----------------------------------

// A textured plane y = -2 and a sphere of radius 2 at the origin, both with `kind`'s defaults
// changed by `edit`, seen from (0, 3, 12) as in the course scene.
template <typename Edit>
Scene extremeScene(TextureKind kind, double texScale, Edit edit) {
  Scene scene = emptyScene();
  int m = addMaterial(scene, kind);
  edit(scene.materials[size_t(m)].texture);
  addPlane(scene, {0, 1, 0}, -2.0, texScale, m);
  addSphere(scene, {0, 0, 0}, 2.0, m);
  addLight(scene, {-6, 10, 6});
  setCamera(scene, {0, 3, 12}, {0, 0, 0}, {0, 1, 0}, 35.0);
  return scene;
}

// The float range's ends for every value that scales a texture, and sphere sizes and positions
// at the ends of it: the texture coordinates, phases and shading overflow there unless clamped
// (mapping.glsl, clampTexCoord; shading.glsl, shade). A scene file refuses positions past
// kMaxCoordinate (scene_limits.h); scenes built in code may hold them, and stay finite.
std::vector<NamedScene> extremeScenes() {
  auto none = [](TextureDesc&) {};
  std::vector<NamedScene> scenes;
  for (double s : {1e-38, 1e-45, 3e38})
    for (TextureKind kind : {TextureKind::Checker, TextureKind::SolidChecker, TextureKind::Noise,
                             TextureKind::Marble, TextureKind::Wood})
      scenes.push_back({"tex_scale " + fmtG(s) + ", " + textureKindName(kind), extremeScene(kind, s, none)});
  for (float squares : {3e38f, 1e-38f})
    for (TextureKind kind : {TextureKind::Checker, TextureKind::SolidChecker})
      scenes.push_back({"squares " + fmtG(squares) + ", " + textureKindName(kind),
                        extremeScene(kind, 1.0, [&](TextureDesc& t) { t.squares = squares; })});
  for (float scale : {3e38f, 1e-38f})
    for (TextureKind kind : {TextureKind::Noise, TextureKind::Marble, TextureKind::Wood, TextureKind::Turbulence,
                             TextureKind::DTurbulence})
      for (float strength : {1.0f, 3e38f, -3e38f})
        scenes.push_back({"scale " + fmtG(scale) + ", strength " + fmtG(strength) + ", " + textureKindName(kind),
                          extremeScene(kind, 5.0, [&](TextureDesc& t) {
                            t.scale = scale;
                            if (kind != TextureKind::Noise) t.strength = strength;
                          })});
  auto sphereScene = [](glm::dvec3 eye, glm::dvec3 center, double radius) {
    Scene scene = emptyScene();
    addSphere(scene, center, radius, addMaterial(scene, TextureKind::SolidChecker));
    addLight(scene, {-6, 10, 6});
    setCamera(scene, eye, center, {0, 1, 0}, 35.0);
    return scene;
  };
  scenes.push_back({"radius 3e38 around the camera", sphereScene({0, 3, 12}, {0, 0, 0}, 3e38)});
  scenes.push_back({"radius 1e-38", sphereScene({0, 3, 12}, {0, 0, 0}, 1e-38)});
  scenes.push_back({"radius 1e-45", sphereScene({0, 3, 12}, {0, 0, 0}, 1e-45)});
  scenes.push_back({"sphere 3e38 away", sphereScene({0, 3, 12}, {0, 0, -3e38}, 1e38)});
  scenes.push_back({"camera and sphere 6e38 apart", sphereScene({-3e38, 0, 0}, {3e38, 0, 0}, 3e38)});
  Scene farPlane = extremeScene(TextureKind::Checker, 1.0, none);
  farPlane.planes[0].distance = -3e38;
  farPlane.camera.eye = glm::dvec3(0, 3e38, 12);
  scenes.push_back({"camera and plane 6e38 apart", farPlane});
  return scenes;
}

// Every output (texture coordinates, albedo, and shaded with both filters) is finite (checked
// in render()), and so is the double reference's image.
TEST_F(StabilityTest, ExtremeValuesRenderFinite) {
  const int w = 24, h = 18;
  std::vector<NamedScene> scenes = extremeScenes();
  for (const NamedScene& s : scenes) {
    SCOPED_TRACE(s.name);
    for (uint32_t mode : {uint32_t(OUTPUT_COORDS), uint32_t(OUTPUT_ALBEDO)}) render(s.scene, w, h, mode);
    for (uint32_t filter : {uint32_t(FILTER_POINT), uint32_t(FILTER_BOX)})
      render(s.scene, w, h, OUTPUT_SHADED, 1, filter);
    EXPECT_EQ(renderReference(s.scene, 8, 6, 1, 1).nonFinite, 0u);
  }
}

// Checks far below a pixel (squares 3e38, or tex_scale 1e-38) average to the mean of the two
// colours under the box filter: every texture footprint spans over 1e8 checks, whose average is
// 0.5 up to float rounding (1e-3 allowed). The point kernel samples one check:
// every pixel is one of the two colours. The material reflects only the ambient light (1), so
// the shaded value is the texture colour (the debug outputs have no box filter).
TEST_F(StabilityTest, ChecksFarBelowAPixelAverageToTheirMean) {
  const int w = 24, h = 18;
  auto squares = [](TextureDesc& t) { t.squares = 3e38f; };
  auto none = [](TextureDesc&) {};
  std::vector<NamedScene> scenes = {{"squares 3e38", extremeScene(TextureKind::Checker, 1.0, squares)},
                                    {"tex_scale 1e-38", extremeScene(TextureKind::Checker, 1e-38, none)}};
  const TextureDesc checker = defaultTexture(TextureKind::Checker);
  const glm::vec3 mean = 0.5f * (checker.color1 + checker.color2);
  for (NamedScene& s : scenes) {
    SCOPED_TRACE(s.name);
    s.scene.lights.clear();
    Material& m = s.scene.materials[0];
    m.ambient = glm::vec3(1.0f);
    m.diffuse = m.specular = glm::vec3(0.0f);
    std::vector<float> coords = render(s.scene, w, h, OUTPUT_COORDS);
    std::vector<float> box = render(s.scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX);
    std::vector<float> point = render(s.scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT);
    int planePixels = 0;
    for (size_t i = 0; i < size_t(w) * h; ++i) {
      if (gpuKind(coords, i) != HIT_PLANE) continue;
      ++planePixels;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(box[i * 4 + c], mean[c], 1e-3) << "pixel " << i;
        float p = point[i * 4 + c];
        EXPECT_TRUE(p == checker.color1[c] || p == checker.color2[c]) << "pixel " << i << ": " << p;
      }
    }
    EXPECT_GT(planePixels, w * h / 4);
  }
}

// Colours whose products pass the float range (light, ambient light and material 3e38) shade
// to RADIANCE_LIMIT, not to infinity (or NaN where an overflow meets a zero channel), and the
// double reference clamps alike.
TEST_F(StabilityTest, HugeColoursShadeToTheRadianceLimit) {
  const int w = 16, h = 12;
  Scene scene = emptyScene();
  scene.ambientLight = glm::vec3(3e38f, 3e38f, 0.0f);
  int m = addMaterial(scene, TextureKind::None);
  scene.materials[size_t(m)].ambient = scene.materials[size_t(m)].diffuse =
      scene.materials[size_t(m)].specular = glm::vec3(3e38f);
  addSphere(scene, {0, 0, 0}, 2.0, m);
  addLight(scene, {-6, 10, 6});
  scene.lights[0].color = glm::vec3(3e38f, 0.0f, 3e38f);
  setCamera(scene, {0, 3, 12}, {0, 0, 0}, {0, 1, 0}, 35.0);
  std::vector<float> coords = render(scene, w, h, OUTPUT_COORDS);
  ReferenceImage reference = renderReference(scene, w, h, 1, 1);
  int spherePixels = 0;
  for (uint32_t filter : {uint32_t(FILTER_POINT), uint32_t(FILTER_BOX)}) {
    std::vector<float> shaded = render(scene, w, h, OUTPUT_SHADED, 1, filter);
    for (size_t i = 0; i < size_t(w) * h; ++i) {
      if (gpuKind(coords, i) != HIT_SPHERE) continue;
      ++spherePixels;
      // Red: the ambient product alone passes the limit. Green: nothing but the ambient,
      // clamped before the light's 0 multiplies the diffuse overflow. Blue: lit or not.
      EXPECT_EQ(shaded[i * 4 + 0], float(RADIANCE_LIMIT)) << "pixel " << i;
      EXPECT_EQ(shaded[i * 4 + 1], float(RADIANCE_LIMIT)) << "pixel " << i;
      EXPECT_TRUE(std::isfinite(shaded[i * 4 + 2])) << "pixel " << i;
    }
  }
  EXPECT_GT(spherePixels, 2 * w * h / 10);  // over both filters
  // The reference: as many pixels at the limit in red and green as the kernel's sphere has
  // (the silhouette may differ by a few), and nothing else but the background.
  int atLimit = 0;
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    bool limit = reference.rgb[i * 3] == RADIANCE_LIMIT && reference.rgb[i * 3 + 1] == RADIANCE_LIMIT;
    atLimit += limit;
    if (!limit) {
      EXPECT_EQ(reference.rgb[i * 3], double(scene.background.r)) << "pixel " << i;
    }
  }
  EXPECT_NEAR(atLimit, spherePixels / 2, 4);
  EXPECT_EQ(reference.nonFinite, 0u);
}

// --- 11. coordinates at the scene format's limit -------------------

// A floor kMaxCoordinate below the camera, seen to its horizon, untextured and lit from above the
// camera: towards the horizon the floor is over 1.8e19 from the light, where the squared
// distance overflows a float (shading.glsl measures it scaled down there). Every floor pixel
// but the horizon's row is lit as the float64 reference lights it, within float rounding.
// Measured on lavapipe: 0 of the 1536 floor pixels over 1e-4 (with the distance unscaled, 502:
// the far floor unlit).
TEST_F(StabilityTest, FloorToItsHorizonAtTheLimitIsLitLikeTheReference) {
  const int w = 64, h = 48;
  const double L = kMaxCoordinate;
  Scene scene = emptyScene();
  int grey = addMaterial(scene, TextureKind::None);
  addPlane(scene, {0, 1, 0}, -L, 1.0, grey);
  addLight(scene, {0, L, -L});
  setCamera(scene, {0, L, L}, {0, L, -L}, {0, 1, 0}, 35.0);
  std::vector<float> shaded = render(scene, w, h, OUTPUT_SHADED);
  ReferenceImage reference = renderReference(scene, w, h, 1, 1);
  int floorPixels = 0, over = 0;
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    if (reference.rgb[i * 3] == double(scene.background.r)) continue;
    ++floorPixels;
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(shaded[i * 4 + c]) - reference.rgb[i * 3 + c]));
    if (worst > 1e-4) ++over;
  }
  std::cout << "[floor at the limit] " << over << " of " << floorPixels << " floor pixels over 1e-4\n";
  EXPECT_GT(floorPixels, w * h / 3);
  EXPECT_LE(over, w);  // the horizon's row may fall either side
}

// Objects at opposite corners of the limit's cube (the camera at -kMaxCoordinate on every axis, a
// textured sphere of radius kMaxCoordinate at +kMaxCoordinate, a checkered plane through it, the
// light at another corner) render against the float64 reference as the same scene scaled to 1
// does. Measured on lavapipe at 80 x 60: RMSE 0.00116 at both scales, and at 5e18; 0.176 at 6e18,
// where the corners are over 1.8e19 apart (and 0.0105 at 1e18 with the light's distance
// unscaled).
TEST_F(StabilityTest, CornersOfTheLimitRenderLikeAtUnitScale) {
  const int w = 80, h = 60;
  auto corners = [](double L) {
    Scene scene = emptyScene();
    addSphere(scene, {L, L, L}, L, addMaterial(scene, TextureKind::SolidChecker));
    addPlane(scene, {0, 0, 1}, L, 0.5 * L, addMaterial(scene, TextureKind::Checker));
    addLight(scene, {-L, L, -L});
    setCamera(scene, {-L, -L, -L}, {L, L, L}, {0, 1, 0}, 60.0);
    return scene;
  };
  double rmse[2];
  for (int k = 0; k < 2; ++k) {
    const Scene scene = corners(k == 0 ? 1.0 : kMaxCoordinate);
    std::vector<float> shaded = render(scene, w, h, OUTPUT_SHADED);
    rmse[k] = rmseAgainstReference(shaded.data(), renderReference(scene, w, h, 1, 1));
  }
  std::cout << "[corners] RMSE against the reference: " << fmtG(rmse[0]) << " at scale 1, " << fmtG(rmse[1])
            << " at " << fmtG(kMaxCoordinate) << "\n";
  EXPECT_LE(rmse[1], rmse[0] * 1.01 + 1e-6);
}

}  // namespace
