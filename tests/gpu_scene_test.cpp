// Packing a scene for the GPU: only what the objects use, in the shared layouts.
#include "gpu_scene.h"
#include "parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

const std::string kSourceDir = RAYTEX_SOURCE_DIR;

TEST(GpuScene, CourseSceneUploadsOnlyTheMaterialsItUses) {
  Scene scene = parseSceneFile(kSourceDir + "/scenes/textures.cfg");
  ASSERT_EQ(scene.materials.size(), 8u);
  GpuScene g = buildGpuScene(scene, 64, 48);
  EXPECT_EQ(g.materials.size(), 2u);  // aSolidChecker and aChecker of eight defined
  EXPECT_EQ(g.textureKinds, (1u << TEX_SOLID_CHECKER) | (1u << TEX_CHECKER));
  EXPECT_EQ(g.imageLayers, 0);  // anImage is defined but unused: earth.jpg is not loaded
  EXPECT_TRUE(g.imagePixels.empty());
  ASSERT_EQ(g.spheres.size(), 1u);
  ASSERT_EQ(g.planes.size(), 1u);
  EXPECT_EQ(g.materials[g.spheres[0].material].textureKind, uint32_t(TEX_SOLID_CHECKER));
  EXPECT_EQ(g.materials[g.planes[0].material].textureKind, uint32_t(TEX_CHECKER));
  EXPECT_EQ(g.frame.sphereCount, 1u);
  EXPECT_EQ(g.frame.planeCount, 1u);
  EXPECT_EQ(g.frame.lightCount, uint32_t(scene.lights.size()));
  // The plane's frame for n = (0,1,0): t = +x, b = +z, s = tex_scale.
  EXPECT_EQ(g.planes[0].tangentScale, glm::vec4(1, 0, 0, 5));
  EXPECT_EQ(g.planes[0].binormal, glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(g.planes[0].normalDistance, glm::vec4(0, 1, 0, -2));
  // No noise kind in use: the permutation table is left empty.
  EXPECT_EQ(g.noise.perm[1], glm::uvec4(0));
}

TEST(GpuScene, NoiseTableIsFilledWhenANoiseKindIsUsed) {
  Scene scene = parseSceneText(
      "material m { texture = marble { }; }\nsphere { center = (0,0,0); radius = 1; m; }\n", "t.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  EXPECT_EQ(g.textureKinds, 1u << TEX_MARBLE);
  uint32_t sum = 0;
  for (int i = 0; i < 256; ++i) sum += g.noise.perm[i >> 2][i & 3];
  EXPECT_EQ(sum, 255u * 256u / 2u);  // a permutation of 0..255
}

TEST(GpuScene, ObjectsWithoutMaterialGetTheDefault) {
  Scene scene = parseSceneText("sphere { center = (0,0,0); radius = 1; }\n", "t.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  ASSERT_EQ(g.materials.size(), 1u);
  EXPECT_EQ(g.materials[0].textureKind, uint32_t(TEX_NONE));
  EXPECT_EQ(g.textureKinds, 1u << TEX_NONE);
}

TEST(GpuScene, CameraFrameFollowsFovAndAspect) {
  Camera c;
  c.eye = {0, 0, 5};
  c.lookat = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fovY = 90.0f;
  gpu::Frame f = cameraFrame(c, 200, 100);
  EXPECT_NEAR(f.cameraForward.z, -1.0f, 1e-6f);
  EXPECT_NEAR(f.cameraUp.y, 1.0f, 1e-6f);     // tan(45 deg)
  EXPECT_NEAR(f.cameraRight.x, 2.0f, 1e-6f);  // tan(45 deg) * aspect 2
  EXPECT_EQ(f.width, 200u);
  EXPECT_EQ(f.height, 100u);
}

TEST(GpuScene, MissingOrBrokenImageIsASceneErrorAtTheFileKey) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "raytex_gpu_scene_images";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "broken.png") << "PNG? no";
  for (const char* file : {"missing.png", "broken.png"}) {
    std::string text = std::string("material m {\n  texture = image {\n    file = \"") + file +
                       "\";\n  };\n}\nsphere { center = (0,0,0); radius = 1; m; }\n";
    Scene scene = parseSceneText(text, (dir / "s.cfg").string());
    try {
      buildGpuScene(scene, 8, 8);
      FAIL() << "expected SceneError for " << file;
    } catch (const SceneError& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind((dir / "s.cfg").string() + ":3:12: ", 0), 0u) << msg;
      EXPECT_NE(msg.find(file), std::string::npos) << msg;
    }
  }
}

TEST(GpuScene, ImagesShareOneArrayLayerPerFile) {
  Scene scene = parseSceneFile(kSourceDir + "/scenes/textures.cfg");
  for (Sphere& s : scene.spheres)
    for (size_t i = 0; i < scene.materials.size(); ++i)
      if (scene.materials[i].name == "anImage") s.material = int(i);
  GpuScene g = buildGpuScene(scene, 8, 8);
  EXPECT_EQ(g.imageLayers, 1);
  EXPECT_EQ(g.imageWidth, 2048);
  EXPECT_EQ(g.imageHeight, 1024);
  EXPECT_EQ(g.imagePixels.size(), size_t(2048) * 1024 * 4);
}

}  // namespace
