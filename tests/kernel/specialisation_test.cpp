// Kernels specialised to a scene (texture kinds per shape, object and light counts built in)
// must render exactly what the unspecialised kernel renders: every kind compiled in and the
// loops bounded by Frame's counts. Scenes at and over MAX_SPECIALISED_COUNT cover both the
// unrolled and the run-time loops. Kernels built around a scene's values (bakeScene, what
// raytex render uses) must render exactly what the kernel reading them from buffers renders.
#include "support/course_scene.h"
#include "support/files.h"
#include "support/gpu_fixture.h"
#include "gpu_scene.h"
#include "parser.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

constexpr uint32_t kWidth = 80, kHeight = 60;

std::string header() {
  return "#include \"texture_include.cfg\"\n"
         "camera { eye = (0, 3, 12); lookat = (0, -0.5, 0); up = (0, 1, 0); fov = 35; }\n"
         "ambient_light = (1, 1, 1);\n";
}

Scene parse(const std::string& text) { return parseSceneText(text, kSourceDir + "/scenes/specialisation-test.cfg"); }

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

// Bit for bit, every output, both filters, one and four samples: the values folded into the
// kernel's code are the same floats, and the operations on them the same.
TEST_F(SpecialisationTest, BakedKernelsMatchTheUniformBuffers) {
  const char* materials[] = {"aSolidChecker", "aNoise",      "aMarble",       "aWood",
                             "anImage",       "aTurbulence", "aDturbulence", "aChecker"};
  for (const char* m : materials) {
    Scene scene = courseScene(m, "aChecker");
    ASSERT_TRUE(bakeScene(buildGpuScene(scene, kWidth, kHeight)).enabled);
    for (uint32_t mode : {uint32_t(OUTPUT_SHADED), uint32_t(OUTPUT_COORDS), uint32_t(OUTPUT_ALBEDO)})
      for (uint32_t filter : {uint32_t(FILTER_POINT), uint32_t(FILTER_BOX)})
        for (uint32_t side : {1u, 2u}) {
          if (mode != OUTPUT_SHADED && (filter == FILTER_BOX || side > 1)) continue;
          std::vector<float> baked = render(scene, kWidth, kHeight, mode, side, filter, nullptr, true);
          std::vector<float> buffers = render(scene, kWidth, kHeight, mode, side, filter);
          EXPECT_EQ(baked, buffers) << m << " output " << mode << " filter " << filter << " side " << side;
        }
  }
  // Up to MAX_BAKED_SPHERES spheres with four materials, two planes and two lights.
  Scene row = rowScene(int(MAX_BAKED_SPHERES));
  ASSERT_TRUE(bakeScene(buildGpuScene(row, kWidth, kHeight)).enabled);
  EXPECT_EQ(render(row, kWidth, kHeight, OUTPUT_SHADED, 1, FILTER_POINT, nullptr, true),
            render(row, kWidth, kHeight, OUTPUT_SHADED));
}

TEST_F(SpecialisationTest, OnlySmallScenesAreBaked) {
  EXPECT_TRUE(bakeScene(buildGpuScene(rowScene(int(MAX_BAKED_SPHERES)), 8, 8)).enabled);
  EXPECT_FALSE(bakeScene(buildGpuScene(rowScene(int(MAX_BAKED_SPHERES) + 1), 8, 8)).enabled);
}

// The check can fail: a kernel baked with another sphere radius renders another image.
TEST_F(SpecialisationTest, AWrongBakedValueChangesTheImage) {
  Scene scene = courseScene("aChecker", "aChecker");
  BakedScene baked = bakeScene(buildGpuScene(scene, kWidth, kHeight));
  gpu::Sphere sphere;
  std::memcpy(&sphere, baked.words.data() + BAKED_SPHERE_WORD, sizeof(sphere));
  sphere.centerRadius.w *= 0.5f;
  std::memcpy(baked.words.data() + BAKED_SPHERE_WORD, &sphere, sizeof(sphere));
  EXPECT_NE(render(scene, kWidth, kHeight, OUTPUT_SHADED, 1, FILTER_POINT, nullptr, false, &baked),
            render(scene, kWidth, kHeight, OUTPUT_SHADED));
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

// Scenes that fill one of the kernel's uniform blocks (MAX_UNIFORM_SPHERES, MAX_PLANES, MAX_LIGHTS),
// or hold the most spheres (MAX_SPHERES, in storage buffers):
// the items before the last are out of view (behind the camera) or dark, so the centre pixel
// is the last sphere, lit by the last light, over the last plane. (One block at a time: on
// lavapipe a loop nest stops after 65535 iterations, and MAX_LIGHTS shadow rays each testing
// MAX_SPHERES spheres are more.)
TEST_F(SpecialisationTest, FullBlocksRenderTheirLastItems) {
  auto repeat = [](int n, const std::string& line) {
    std::string text;
    for (int i = 0; i < n; ++i) text += line + "\n";
    return text;
  };
  const std::string light = "light { position = (-6, 10, 6); color = (1, 1, 1); }\n";
  const std::string sphere = "sphere { center = (0, 0, 0); radius = 2; aChecker; }\n";
  const std::string plane = "plane { normal = (0, 1, 0); distance = -2; aChecker; }\n";
  const std::string darkLight = "light { position = (0, 10, 6); color = (0, 0, 0); }";
  const std::string hiddenSphere = "sphere { center = (0, 0, 40); radius = 1; aChecker; }";
  const std::string hiddenPlane = "plane { normal = (0, 0, 1); distance = 40; aChecker; }";
  const std::string scenes[] = {
      header() + repeat(MAX_LIGHTS - 1, darkLight) + light + sphere + plane,
      header() + light + repeat(MAX_UNIFORM_SPHERES - 1, hiddenSphere) + sphere + plane,
      header() + light + repeat(MAX_SPHERES - 1, hiddenSphere) + sphere + plane,
      header() + light + sphere + repeat(MAX_PLANES - 1, hiddenPlane) + plane,
  };
  const uint32_t w = 16, h = 12;
  for (const std::string& text : scenes) {
    Scene scene = parse(text);
    SCOPED_TRACE(std::to_string(scene.lights.size()) + " lights, " + std::to_string(scene.spheres.size()) +
                 " spheres, " + std::to_string(scene.planes.size()) + " planes");
    std::vector<float> coords = render(scene, w, h, OUTPUT_COORDS);
    EXPECT_EQ(coords[((h / 2) * w + w / 2) * 4 + 3], float(HIT_SPHERE));  // the last sphere
    EXPECT_EQ(coords[((h - 1) * w + w / 2) * 4 + 3], float(HIT_PLANE));   // the last plane, below it
    // Lit by the last light: well over the ambient term alone, aChecker's 0.15 of the albedo.
    const size_t centre = ((h / 2) * w + w / 2) * 4;
    std::vector<float> albedo = render(scene, w, h, OUTPUT_ALBEDO);
    std::vector<float> shaded = render(scene, w, h, OUTPUT_SHADED);
    for (int c = 0; c < 3; ++c) EXPECT_GT(shaded[centre + c], 1.5f * 0.15f * albedo[centre + c]) << "channel " << c;
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
