// Kernels specialised to a scene (texture kinds per shape, object and light counts built in)
// must render exactly what the unspecialised kernel renders: every kind compiled in and the
// loops bounded by Frame's counts. Scenes at and over MAX_SPECIALISED_COUNT cover both the
// unrolled and the run-time loops.
#include "gpu_fixture.h"
#include "gpu_scene.h"
#include "parser.h"

#include <gtest/gtest.h>

#include <string>

namespace {

const std::string kSourceDir = RAYTEX_SOURCE_DIR;
constexpr uint32_t kWidth = 80, kHeight = 60;

std::string header() {
  return "#include \"texture_include.cfg\"\n"
         "camera { eye = (0, 3, 12); lookat = (0, -0.5, 0); up = (0, 1, 0); fov = 35; }\n"
         "ambient_light = (1, 1, 1);\n";
}

Scene parse(const std::string& text) { return parseSceneText(text, kSourceDir + "/scenes/specialisation-test.cfg"); }

// A course material on the sphere, another on the plane, one light.
Scene courseScene(const std::string& sphereMaterial, const std::string& planeMaterial) {
  return parse(header() + "light { position = (-6, 10, 6); color = (1, 1, 1); }\n" +
               "sphere { center = (0, 0, 0); radius = 2.0; " + sphereMaterial + "; }\n" +
               "plane { normal = (0, 1, 0); distance = -2.0; tex_scale = 5.0; " + planeMaterial + "; }\n");
}

// `spheres` small spheres in a row casting shadows from two lights, over two planes.
Scene rowScene(int spheres) {
  std::string text = header() + "light { position = (-6, 10, 6); color = (0.6, 0.6, 0.6); }\n" +
                     "light { position = (6, 8, 4); color = (0.5, 0.4, 0.3); }\n" +
                     "plane { normal = (0, 1, 0); distance = -2.0; tex_scale = 5.0; aChecker; }\n" +
                     "plane { normal = (0, 0, 1); distance = -30.0; tex_scale = 3.0; aSolidChecker; }\n";
  const char* materials[] = {"aMarble", "aChecker", "anImage", "aWood"};
  for (int i = 0; i < spheres; ++i)
    text += "sphere { center = (" + std::to_string(-4.8 + 1.2 * i) + ", -1.4, 0); radius = 0.55; " + materials[i % 4] + "; }\n";
  return parse(text);
}

class SpecialisationTest : public RenderTest {
 protected:
  // Renders `scene` specialised and unspecialised; returns the number of differing floats.
  size_t differences(const Scene& scene, uint32_t filter) {
    const SceneShape unspecialised;
    std::vector<float> specialised = render(scene, kWidth, kHeight, OUTPUT_SHADED, 1, filter);
    std::vector<float> general = render(scene, kWidth, kHeight, OUTPUT_SHADED, 1, filter, &unspecialised);
    EXPECT_EQ(countNonFinite(specialised), 0u);
    size_t n = 0;
    for (size_t i = 0; i < specialised.size(); ++i) n += specialised[i] != general[i];
    return n;
  }
};

TEST_F(SpecialisationTest, CourseMaterialsMatchTheUnspecialisedKernel) {
  const char* materials[] = {"aSolidChecker", "aNoise",      "aMarble",       "aWood",
                             "anImage",       "aTurbulence", "aDturbulence", "aChecker"};
  for (uint32_t filter : {uint32_t(FILTER_POINT), uint32_t(FILTER_BOX)})
    for (const char* m : materials)
      EXPECT_EQ(differences(courseScene(m, "aChecker"), filter), 0u) << m << " filter " << filter;
  EXPECT_EQ(differences(courseScene("aChecker", "aMarble"), FILTER_POINT), 0u);
}

TEST_F(SpecialisationTest, CountsAtAndOverTheLimitMatch) {
  for (int spheres : {MAX_SPECIALISED_COUNT, MAX_SPECIALISED_COUNT + 1}) {
    Scene scene = rowScene(spheres);
    SceneShape shape = sceneShape(scene);
    EXPECT_EQ(shape.sphereCount, spheres <= MAX_SPECIALISED_COUNT ? uint32_t(spheres) : COUNT_FROM_FRAME);
    EXPECT_EQ(shape.planeCount, 2u);
    EXPECT_EQ(shape.lightCount, 2u);
    EXPECT_EQ(differences(scene, FILTER_POINT), 0u) << spheres << " spheres";
  }
}

// The check can fail: a kernel built for one sphere fewer than the scene has misses it.
TEST_F(SpecialisationTest, AWrongCountChangesTheImage) {
  Scene scene = rowScene(3);
  SceneShape shape = sceneShape(scene);
  shape.sphereCount = 2;
  std::vector<float> right = render(scene, kWidth, kHeight, OUTPUT_SHADED);
  std::vector<float> wrong = render(scene, kWidth, kHeight, OUTPUT_SHADED, 1, FILTER_POINT, &shape);
  EXPECT_NE(right, wrong);
}

}  // namespace
