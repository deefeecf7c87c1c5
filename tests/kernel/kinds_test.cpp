// Every procedural row of the texture-kind table (host/scene/texture_kinds.cpp), with its defaults
// on a sphere and a floor, against its float64 oracle (host/reference/texture.cpp): the point kernel's
// texture colour per pixel, and the box kernel's image closer to the supersampled reference
// than the point kernel's. A new kind is tested here with no edit.
#include "support/gpu_fixture.h"
#include "support/reference_rmse.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"
#include "texture.h"
#include "texture_kinds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

std::vector<std::string> proceduralKinds() {
  std::vector<std::string> names;
  for (const TextureKindInfo& info : textureKinds())
    if (info.kind != TextureKind::Image) names.push_back(info.name);
  return names;
}

// The course scene's view, with kind's defaults on the sphere and the floor.
Scene kindScene(const std::string& kind) {
  return parseSceneText("camera { eye = (0, 3, 12); lookat = (0, -0.5, 0); fov = 35; }\n"
                        "light { position = (-6, 10, 6); }\n"
                        "material k { texture = " + kind + "; }\n"
                        "sphere { center = (0, 0, 0); radius = 2; k; }\n"
                        "plane { normal = (0, 1, 0); distance = -2; tex_scale = 5; k; }\n",
                        kind + ".cfg");
}

class KindTest : public RenderTest, public ::testing::WithParamInterface<std::string> {};

// Away from silhouettes, the far floor and the poles, the kernel's texture colour equals the
// oracle's at the reference hit; a pixel within float rounding of a pattern edge may differ.
TEST_P(KindTest, PointColourMatchesTheOracle) {
  const int w = 96, h = 72;
  Scene scene = kindScene(GetParam());
  const TextureDesc& texture = scene.materials[0].texture;
  std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);
  int checked = 0, mismatches = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      glm::dvec3 d = referenceRayDirection(scene.camera, w, h, x, y);
      ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, d);
      if (hit.kind == 0 || hit.edgeMargin < 2e-3 || (hit.kind == 1 && hit.t > 60.0) || (hit.kind == 2 && std::abs(hit.n.y) > 0.999))
        continue;
      glm::dvec3 expected = textureColorReference(texture, hit.tc);
      const float* g = &gpu[size_t(y * w + x) * 4];
      double err = 0.0;
      for (int c = 0; c < 3; ++c) err = std::max(err, std::abs(double(g[c]) - expected[c]));
      ++checked;
      mismatches += err > 2e-3;
    }
  }
  EXPECT_GT(checked, w * h / 3);
  EXPECT_LE(mismatches, checked / 100) << GetParam() << ": " << mismatches << " of " << checked << " pixels differ";
}

// The box filter is closer than point sampling to the 8x8-supersampled reference, each at one
// sample per pixel.
TEST_P(KindTest, BoxFilterBeatsPointSampling) {
  const int w = 96, h = 72;
  Scene scene = kindScene(GetParam());
  ReferenceImage ref = renderReference(scene, w, h, 8);
  double point = rmseAgainstReference(render(scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT).data(), ref);
  double box = rmseAgainstReference(render(scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX).data(), ref);
  EXPECT_LT(box, point) << GetParam() << ": RMSE box " << box << ", point " << point;
}

// The floor toward the horizon (camera 1 above it, 8 degrees down, 60 degree fov), lit by the
// ambient term alone: in the band of floor 10 or more units away, where a pixel spans many
// cells of the pattern, the box filter is closer to the 16x16 reference than point sampling,
// both at one sample per pixel, and finite everywhere.
TEST_P(KindTest, HorizonBandBoxBeatsPointSampling) {
  Scene scene = parseSceneText("material k { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0);"
                               " texture = " + GetParam() + "; }\n"
                               "camera { eye = (0, 1, 0); lookat = (0, 0.8594, -1); up = (0, 1, 0); fov = 60; }\n"
                               "ambient_light = (1, 1, 1);\n"
                               "plane { normal = (0, 1, 0); distance = 0; tex_scale = 1; k; }\n",
                               "horizon.cfg");
  const int w = 96, h = 72;
  ReferenceImage ref = renderReference(scene, w, h, 16);
  std::vector<bool> band(size_t(w) * h, false);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, referenceRayDirection(scene.camera, w, h, x, y));
      band[size_t(y) * w + x] = hit.kind == 1 && hit.t >= 10.0;
    }
  std::vector<float> point1 = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT);
  std::vector<float> box1 = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX);
  EXPECT_EQ(countNonFinite(box1), 0u);
  double point = rmseAgainstReference(point1.data(), ref, &band), box = rmseAgainstReference(box1.data(), ref, &band);
  RecordProperty("band_rmse_point_box", std::to_string(point) + " " + std::to_string(box));
  EXPECT_LT(box, point) << GetParam() << ": band RMSE box " << box << ", point " << point;
}

INSTANTIATE_TEST_SUITE_P(Rows, KindTest, ::testing::ValuesIn(proceduralKinds()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
