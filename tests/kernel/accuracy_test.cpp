// The GPU kernel against the float64 reference renderer (host/reference/reference_render.cpp):
// equal sampling must give equal images, and supersampling must converge to the
// reference without a bias floor.
#include "support/course_scene.h"
#include "support/gpu_fixture.h"
#include "support/reference_rmse.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// The checker floor toward the horizon (camera 1 above the floor, 8 degrees
// down, 60 degree fov, unit checks), lit by the ambient term alone so pixels are texture.
Scene horizonScene() {
  return parseSceneText(
      "material c { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0);"
      " texture = checker { color1 = (1, 1, 1); color2 = (0, 0, 0); squares = 1; }; }\n"
      "camera { eye = (0, 1, 0); lookat = (0, 0.8594, -1); up = (0, 1, 0); fov = 60; }\n"  // tan(8 deg) = 0.1405
      "ambient_light = (1, 1, 1);\n"
      "background = (0.5, 0.5, 0.5);\n"
      "plane { normal = (0, 1, 0); distance = 0; tex_scale = 1; c; }\n",
      "horizon.cfg");
}

class AccuracyTest : public RenderTest, public ::testing::WithParamInterface<const char*> {};

// Same scene, same 2x2 stratified sample positions: the float32 kernel and the float64
// reference agree except where a sample lands on the other side of an edge.
TEST_P(AccuracyTest, GpuMatchesReferenceAtEqualSampling) {
  const std::string material = GetParam();
  Scene scene = courseScene(material);
  const int w = 128, h = 96, n = 2;
  std::vector<float> gpu = render(scene, w, h, OUTPUT_SHADED, n);
  ReferenceImage ref = renderReference(scene, w, h, n);
  EXPECT_EQ(countNonFinite(gpu), 0u);
  EXPECT_EQ(ref.nonFinite, 0u);
  double sumAbs = 0.0;
  int outliers = 0;
  for (int i = 0; i < w * h; ++i) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
      double d = std::abs(double(gpu[size_t(i) * 4 + c]) - ref.rgb[size_t(i) * 3 + c]);
      sumAbs += d;
      worst = std::max(worst, d);
    }
    outliers += worst > 0.05;
  }
  RecordProperty("mean_abs", std::to_string(sumAbs / (3.0 * w * h)));
  RecordProperty("outliers", outliers);
  // Measured on lavapipe (Mesa 22.3.6): mean 2.0e-5 to 3.2e-5, 1 outlier pixel per material (a
  // horizon check). The limits leave room for other drivers' float rounding at edges.
  EXPECT_LT(sumAbs / (3.0 * w * h), 1e-3) << material;
  EXPECT_LE(outliers, w * h / 200) << material;
}

INSTANTIATE_TEST_SUITE_P(Materials, AccuracyTest,
                         ::testing::Values("aSolidChecker", "aMarble", "anImage", "aDturbulence"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

// Against a 16x16 reference, the error of N x N stratified supersampling of the horizon
// scene falls as N grows: no bias floor.
TEST_F(RenderTest, SupersamplingConvergesToTheReference) {
  Scene scene = horizonScene();
  const int w = 96, h = 72;
  ReferenceImage ref = renderReference(scene, w, h, 16);
  double previous = 1e9;
  std::vector<double> errors;
  for (int n : {1, 2, 4, 8}) {
    std::vector<float> gpu = render(scene, w, h, OUTPUT_SHADED, uint32_t(n));
    EXPECT_EQ(countNonFinite(gpu), 0u);
    double e = rmseAgainstReference(gpu.data(), ref);
    errors.push_back(e);
    EXPECT_LT(e, previous) << n << "x" << n << " samples";
    previous = e;
  }
  RecordProperty("rmse_1_4_16_64_spp", std::to_string(errors[0]) + " " + std::to_string(errors[1]) + " " +
                                           std::to_string(errors[2]) + " " + std::to_string(errors[3]));
  // Measured on lavapipe: RMSE 0.199, 0.094, 0.056, 0.035 at 1, 4, 16, 64 samples per pixel
  // (about spp^-0.4: edges under stratified sampling).
  EXPECT_LT(errors[3], errors[0] / 4.0);
}


// The horizon band (floor hit at distance >= 10 from the eye): box-filtered checkers at one
// sample per pixel beat 4x4 point supersampling by 3x against a 32x32 reference.
TEST_F(RenderTest, FilteredCheckerBeatsSupersamplingAtTheHorizon) {
  Scene scene = horizonScene();
  const int w = 96, h = 72;
  ReferenceImage ref = renderReference(scene, w, h, 32);
  std::vector<bool> band(size_t(w) * h, false);
  size_t bandPixels = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      ReferenceHit hit = referenceClosestHit(scene, glm::dvec3(scene.camera.eye),
                                             referenceRayDirection(scene.camera, w, h, x, y));
      bool inBand = hit.kind == HIT_PLANE && hit.t >= 10.0;
      band[size_t(y) * w + x] = inBand;
      bandPixels += inBand;
    }
  ASSERT_GT(bandPixels, size_t(w) * 3);

  std::vector<float> point1 = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT);
  std::vector<float> point16 = render(scene, w, h, OUTPUT_SHADED, 4, FILTER_POINT);
  std::vector<float> box1 = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX);
  std::vector<float> box16 = render(scene, w, h, OUTPUT_SHADED, 4, FILTER_BOX);
  for (const auto* img : {&point1, &point16, &box1, &box16}) EXPECT_EQ(countNonFinite(*img), 0u);
  double ePoint1 = rmseAgainstReference((point1).data(), ref, &band), ePoint16 = rmseAgainstReference((point16).data(), ref, &band);
  double eBox1 = rmseAgainstReference((box1).data(), ref, &band), eBox16 = rmseAgainstReference((box16).data(), ref, &band);
  RecordProperty("band_rmse_point1_point16_box1_box16", std::to_string(ePoint1) + " " + std::to_string(ePoint16) +
                                                            " " + std::to_string(eBox1) + " " + std::to_string(eBox16));
  // Measured on lavapipe at 96x72: point 0.502 (1 spp), 0.147 (16 spp); box 0.035 (1 spp),
  // 0.020 (16 spp). The target from the issue: filtered 1 spp within 1/3 of 16-spp point.
  EXPECT_LE(eBox1, ePoint16 / 3.0);
  EXPECT_LT(eBox16, eBox1);  // the footprint shrinks with the sample spacing: still converging
}

}  // namespace
