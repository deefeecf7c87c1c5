// Packing a scene for the GPU: only what the objects use, in the shared layouts.
#include "gpu_scene.h"
#include "scene_limits.h"
#include "parser.h"

#include "support/files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {


TEST(GpuScene, CourseSceneUploadsOnlyTheMaterialsItUses) {
  Scene scene = parseSceneFile(kSourceDir + "/scenes/textures.cfg");
  ASSERT_EQ(scene.materials.size(), 8u);
  GpuScene g = buildGpuScene(scene, 64, 48);
  EXPECT_EQ(g.materials.size(), 2u);  // aSolidChecker and aChecker of eight defined
  EXPECT_EQ(g.shape.kinds(), (1u << TEX_SOLID_CHECKER) | (1u << TEX_CHECKER));
  EXPECT_TRUE(g.imageChains.empty());  // anImage is defined but unused: earth.jpg is not loaded
  EXPECT_EQ(g.shape.imageCount, 0u);
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
  // Camera-relative (eye (0, 3, 12)): the plane y = -2 lies 5 below the eye, the sphere at
  // the origin at (0, -3, -12); the camera sits at u_p/s = 0/5, v_p/s = 12/5 = 2.4: tile 2,
  // fraction 0.4; the 2D checker has no solid period, so the solid offset is eye/5.
  EXPECT_EQ(g.planes[0].normalDistance, glm::vec4(0, 1, 0, -5));
  EXPECT_EQ(g.spheres[0].centerRadius, glm::vec4(0, -3, -12, 2));
  EXPECT_EQ(g.frame.eye, glm::vec4(0.0f));
  EXPECT_NEAR(g.planes[0].uvOffset.x, 0.0f, 1e-6f);
  EXPECT_NEAR(g.planes[0].uvOffset.y, 0.4f, 1e-6f);
  EXPECT_EQ(g.planes[0].uvOffset.z, 0.0f);
  EXPECT_EQ(g.planes[0].uvOffset.w, 2.0f);
  EXPECT_NEAR(g.planes[0].solidOffset.y, 0.6f, 1e-6f);
  EXPECT_NEAR(g.planes[0].solidOffset.z, 2.4f, 1e-6f);
  // No noise kind in use: the permutation table is left empty.
  EXPECT_EQ(g.noise.pairs[1], glm::uvec4(0));
}

// Without placement the packed placement is the identity, which the kernel applies exactly;
// with it the plane's axes are the turned ones and the image axes follow the upright rule.
TEST(GpuScene, PlacementPacksTheTurnedAxesAndTheIdentityWithoutIt) {
  Scene scene = parseSceneText(
      "material m { texture = checker; }\ncamera { eye = (0.3, 3, 12); }\n"
      "material picture { texture = image { file = \"textures/uv_grid.png\"; }; }\n"
      "sphere { m; }\nplane { picture; }\n"
      "sphere { m; tex_rotate = (0, 90, 0); tex_scale = 0.5; tex_offset = (0.25, 3.5, 0); }\n"
      "plane { m; tex_rotate = (0, 90, 0); tex_scale = 2; tex_offset = (0.5, 0.25, 0); }\n",
      kSourceDir + "/t.cfg");
  GpuScene g = buildGpuScene(scene, 64, 48);
  EXPECT_EQ(g.spheres[0].texRotation, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(g.spheres[0].solidOffset, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(g.spheres[0].clampV, 1u);
  EXPECT_EQ(g.planes[0].texRotation, glm::vec4(0, 0, 0, 1));
  // The floor's image: rows along +x, its top towards -z (so down is +z); the eye's x, z
  // reduced mod 1 are the offsets of column and row.
  EXPECT_EQ(g.planes[0].imageRight, glm::vec4(1, 0, 0, 0.3f));
  EXPECT_EQ(g.planes[0].imageDown, glm::vec4(0, 0, 1, 0));
  // A quarter turn about +y: R^-1 is the half angle's quaternion conjugated.
  const float h = float(std::sqrt(0.5));
  for (int k : {0, 1, 2, 3}) {
    EXPECT_NEAR(g.spheres[1].texRotation[k], glm::vec4(0, -h, 0, h)[k], 1e-7f);
    EXPECT_NEAR(g.planes[1].texRotation[k], glm::vec4(0, -h, 0, h)[k], 1e-7f);
  }
  EXPECT_EQ(g.spheres[1].solidOffset.w, 0.5f);
  EXPECT_EQ(g.spheres[1].uOffset, 0.25f);
  EXPECT_EQ(g.spheres[1].vOffset, 1.5f);  // mod 2: the checker's tile parity is kept
  EXPECT_EQ(g.spheres[1].clampV, 0u);
  // The floor's u axis +x turned a quarter about +y is -z, v's +z is +x.
  for (int k : {0, 1, 2}) {
    EXPECT_NEAR(g.planes[1].tangentScale[k], glm::vec4(0, 0, -1, 0)[k], 1e-7f);
    EXPECT_NEAR(g.planes[1].binormal[k], glm::vec4(1, 0, 0, 0)[k], 1e-7f);
  }
  EXPECT_EQ(g.planes[1].tangentScale.w, 2.0f);
  // A plane whose texture is not an image has no image axes: its lanes read one texel in the
  // kernel's masked image lookups.
  EXPECT_EQ(g.planes[1].imageRight, glm::vec4(0.0f));
  EXPECT_EQ(g.planes[1].imageDown, glm::vec4(0.0f));
  // u at the eye: (eye . (0, 0, -1)) / 2 + 0.5 = -5.5: tile -6, fraction 0.5; v: 0.15 + 0.25.
  EXPECT_NEAR(g.planes[1].uvOffset.x, 0.5f, 1e-6f);
  EXPECT_NEAR(g.planes[1].uvOffset.y, 0.4f, 1e-6f);
  EXPECT_EQ(g.planes[1].uvOffset.z, 4096.0f - 6.0f);
  // The kernel applies placement (SPEC_TEXTURE_PLACEMENT) only where a packed frame cannot
  // hold it: a turned plane or a placed sphere, not a plane's tex_scale or tex_offset.
  EXPECT_EQ(g.shape.placed, 1u);
  EXPECT_EQ(sceneShape(parseSceneText("plane { tex_scale = 2; tex_offset = (1, 2, 3); }", "t.cfg")).placed, 0u);
  EXPECT_EQ(sceneShape(parseSceneText("plane { tex_rotate = (0, 1, 0); }", "t.cfg")).placed, 1u);
  EXPECT_EQ(sceneShape(parseSceneText("sphere { tex_scale = 2; }", "t.cfg")).placed, 1u);
  EXPECT_EQ(sceneShape(parseSceneText("sphere { tex_offset = (0, 0, 1); }", "t.cfg")).placed, 1u);
  EXPECT_EQ(sceneShape(parseSceneText("sphere { }", "t.cfg")).placed, 0u);
}

TEST(GpuScene, ShapeHasTheKindsPerShapeAndTheCountsUpToTheLimit) {
  Scene scene = parseSceneFile(kSourceDir + "/scenes/textures.cfg");
  SceneShape shape = buildGpuScene(scene, 8, 8).shape;
  EXPECT_EQ(shape.sphereKinds, 1u << TEX_SOLID_CHECKER);
  EXPECT_EQ(shape.planeKinds, 1u << TEX_CHECKER);
  EXPECT_EQ(shape.sphereCount, 1u);
  EXPECT_EQ(shape.planeCount, 1u);
  EXPECT_EQ(shape.lightCount, 1u);
  std::string text = "material m { texture = wood { }; }\n";
  for (int i = 0; i <= MAX_SPECIALISED_COUNT; ++i) text += "sphere { center = (0,0,0); radius = 1; m; }\n";
  shape = sceneShape(parseSceneText(text, "many.cfg"));
  EXPECT_EQ(shape.sphereKinds, 1u << TEX_WOOD);
  EXPECT_EQ(shape.planeKinds, 0u);  // no planes
  EXPECT_EQ(shape.sphereCount, COUNT_FROM_FRAME);  // MAX_SPECIALISED_COUNT + 1: a loop
  EXPECT_EQ(shape.planeCount, 0u);
  EXPECT_EQ(shape.lightCount, 0u);
}

TEST(GpuScene, NoiseTableIsFilledWhenANoiseKindIsUsed) {
  Scene scene = parseSceneText(
      "material m { texture = marble { }; }\nsphere { center = (0,0,0); radius = 1; m; }\n", "t.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  EXPECT_EQ(g.shape.kinds(), 1u << TEX_MARBLE);
  uint32_t sum = 0;
  for (int i = 0; i < 256; ++i) sum += g.noise.pairs[i >> 2][i & 3] & 0xFFFFu;
  EXPECT_EQ(sum, 255u * 256u / 2u);  // a permutation of 0..255
}

// Far from the origin the offsets carry the camera's position modulo the texture period,
// computed in double: the tile index keeps its parity (mod 4096), solid coordinates their
// phase (solid checker: period 2/squares; noise kinds: 256/scale).
TEST(GpuScene, FarCameraFoldsIntoPeriodicTextureOffsets) {
  Scene scene = parseSceneText(
      "material c { texture = solid_checker { squares = 4; }; }\n"
      "camera { eye = (1000000.3, 3, -2000001.7); lookat = (1000000.3, 0, -2000011.7); }\n"
      "plane { normal = (0, 1, 0); distance = 0; tex_scale = 2; c; }\n",
      "far.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  const gpu::Plane& p = g.planes[0];
  EXPECT_FLOAT_EQ(p.normalDistance.w, -3.0f);
  // u_p/s = 1000000.3 / 2 = 500000.15: tile 500000 mod 4096 = 288, fraction 0.15.
  EXPECT_NEAR(p.uvOffset.x, 0.15f, 1e-6f);
  EXPECT_EQ(p.uvOffset.z, 288.0f);
  // v_p/s = -2000001.7 / 2 = -1000000.85: tile -1000001; 1000001 = 4096 * 244 + 577, so
  // -1000001 mod 4096 = 4096 - 577 = 3519 (odd, like -1000001); fraction 0.15.
  EXPECT_NEAR(p.uvOffset.y, 0.15f, 1e-6f);
  EXPECT_EQ(p.uvOffset.w, 3519.0f);
  // Solid: eye/2 modulo 2/4 = 0.5: 500000.15 -> 0.15, 1.5 -> 0.0, -1000000.85 -> 0.15.
  EXPECT_NEAR(p.solidOffset.x, 0.15f, 1e-6f);
  EXPECT_NEAR(p.solidOffset.y, 0.0f, 1e-6f);
  EXPECT_NEAR(p.solidOffset.z, 0.15f, 1e-6f);
}

TEST(GpuScene, ObjectsWithoutMaterialGetTheDefault) {
  Scene scene = parseSceneText("sphere { center = (0,0,0); radius = 1; }\n", "t.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  ASSERT_EQ(g.materials.size(), 1u);
  EXPECT_EQ(g.materials[0].textureKind, uint32_t(TEX_NONE));
  EXPECT_EQ(g.shape.kinds(), 1u << TEX_NONE);
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

TEST(GpuScene, MissingOrBrokenImageIsAnImageInputErrorAtTheFileKey) {
  namespace fs = std::filesystem;
  fs::path dir = freshTempDir("gpu_scene_images");
  writeFile(dir / "broken.png", "PNG? no");
  for (const char* file : {"missing.png", "broken.png"}) {
    std::string text = std::string("material m {\n  texture = image {\n    file = \"") + file +
                       "\";\n  };\n}\nsphere { center = (0,0,0); radius = 1; m; }\n";
    Scene scene = parseSceneText(text, (dir / "s.cfg").string());
    try {
      buildGpuScene(scene, 8, 8);
      FAIL() << "expected ImageInputError for " << file;
    } catch (const ImageInputError& e) {
      EXPECT_TRUE(e.located);
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind((dir / "s.cfg").string() + ":3:12: ", 0), 0u) << msg;
      EXPECT_NE(msg.find(file), std::string::npos) << msg;
    }
  }
}

TEST(GpuScene, ImagesKeepOneChainPerFileAtItsOwnSize) {
  Scene scene = parseSceneFile(kSourceDir + "/scenes/textures.cfg");
  for (Sphere& s : scene.spheres)
    for (size_t i = 0; i < scene.materials.size(); ++i)
      if (scene.materials[i].name == "anImage") s.material = int(i);
  GpuScene g = buildGpuScene(scene, 8, 8, PackOptions{false});
  ASSERT_EQ(g.imageChains.size(), 1u);
  EXPECT_EQ(g.shape.imageCount, 1u);
  EXPECT_EQ(g.imageChains[0].width, 2048);
  EXPECT_EQ(g.imageChains[0].height, 1024);
  EXPECT_EQ(g.imageChains[0].pixels.size(), size_t(2048) * 1024 * 4);
}

}  // namespace

TEST(GpuScene, MoreMaterialsThanTheKernelHoldsIsASceneError) {
  std::string text;
  for (int i = 0; i <= MAX_MATERIALS; ++i) {
    text += "material m" + std::to_string(i) + " { diffuse = (0.5, 0.5, 0.5); }\n";
    text += "sphere { center = (" + std::to_string(i) + ", 0, 0); radius = 0.5; m" + std::to_string(i) + "; }\n";
  }
  Scene scene = parseSceneText(text, "many.cfg");
  try {
    buildGpuScene(scene, 8, 8);
    FAIL() << "no error for " << MAX_MATERIALS + 1 << " materials";
  } catch (const SceneError& e) {
    // The sphere with the first material over the limit: line 2 * MAX_MATERIALS + 2.
    EXPECT_EQ(std::string(e.what()), "many.cfg:" + std::to_string(2 * MAX_MATERIALS + 2) +
                                         ":1: the scene's objects use more than 256 materials");
  }
  scene.spheres.pop_back();  // exactly MAX_MATERIALS: fine
  EXPECT_EQ(buildGpuScene(scene, 8, 8).materials.size(), size_t(MAX_MATERIALS));
}

namespace {

// max + 1 copies of `block`, one per line: the parse stops at the one over `max`, on line
// max + 1; a scene built in code with one more is refused by buildGpuScene in the same words.
void expectCountLimit(const std::string& block, int max, const std::string& what) {
  std::string text;
  for (int i = 0; i < max; ++i) text += block + "\n";
  const std::string message = "many.cfg:" + std::to_string(max + 1) + ":1: " + what.substr(0, what.size() - 1) + " " +
                              std::to_string(max + 1) + " is over the limit: raytex renders at most " +
                              std::to_string(max) + " " + what;
  Scene scene = parseSceneText(text, "many.cfg");  // exactly `max`: fine
  EXPECT_NO_THROW(buildGpuScene(scene, 8, 8));
  try {
    parseSceneText(text + block + "\n", "many.cfg");
    ADD_FAILURE() << "no error for " << max + 1 << " " << what;
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
  if (what == "spheres") scene.spheres.push_back(scene.spheres.back()), scene.spheres.back().loc.line = max + 1;
  if (what == "planes") scene.planes.push_back(scene.planes.back()), scene.planes.back().loc.line = max + 1;
  if (what == "lights") scene.lights.push_back(scene.lights.back()), scene.lights.back().loc.line = max + 1;
  try {
    buildGpuScene(scene, 8, 8);
    ADD_FAILURE() << "no error for " << max + 1 << " " << what << " built in code";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

}  // namespace

TEST(GpuScene, MoreObjectsOrLightsThanTheKernelHoldsIsASceneError) {
  expectCountLimit("sphere { center = (0, 0, 0); radius = 1; }", MAX_SPHERES, "spheres");
  expectCountLimit("plane { normal = (0, 1, 0); distance = 0; }", MAX_PLANES, "planes");
  expectCountLimit("light { position = (0, 5, 0); }", MAX_LIGHTS, "lights");
}

TEST(SceneLimits, MoreIntersectionTestsPerSampleThanLavapipeLoopsOverIsASceneError) {
  // 256 planes and 8 spheres (too few for a sphere tree): 242 lights are fine ((242 + 1) x 267
  // + 111 = 64992), the 243rd is over (65259).
  std::string text;
  for (int i = 0; i < 256; ++i) text += "plane { normal = (0, 1, 0); distance = " + std::to_string(-i) + "; }\n";
  for (int i = 0; i < 8; ++i) text += "sphere { center = (" + std::to_string(i) + ", 0, 0); radius = 0.5; }\n";
  for (int i = 0; i < 242; ++i) text += "light { position = (0, 10, 0); color = (0.001, 0.001, 0.001); }\n";
  EXPECT_NO_THROW(checkLoopLimit(parseSceneText(text, "pairs.cfg")));
  text += "light { position = (0, 10, 0); }\n";
  Scene scene = parseSceneText(text, "pairs.cfg");
  EXPECT_NO_THROW(buildGpuScene(scene, 8, 8));  // a limit of one driver, checked with the device
  try {
    checkLoopLimit(scene);
    ADD_FAILURE() << "no error for 243 lights and 264 objects";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "pairs.cfg:507:1: the scene has 243 lights and 264 objects every ray tests: "
                                     "(lights + 1) x (objects + 3) + 111 = 65259 loop passes per sample, more than "
                                     "the 65000 the lavapipe driver runs");
  }
}

TEST(SceneLimits, TheCoverageFiltersEdgePassTracesTwiceAndHalvesTheLights) {
  // The same 264 objects: 2 x ((120 + 1) x 267 + 111) = 64836 is fine, 121 lights (65370) over.
  std::string text;
  for (int i = 0; i < 256; ++i) text += "plane { normal = (0, 1, 0); distance = " + std::to_string(-i) + "; }\n";
  for (int i = 0; i < 8; ++i) text += "sphere { center = (" + std::to_string(i) + ", 0, 0); radius = 0.5; }\n";
  for (int i = 0; i < 120; ++i) text += "light { position = (0, 10, 0); color = (0.001, 0.001, 0.001); }\n";
  EXPECT_NO_THROW(checkLoopLimit(parseSceneText(text, "pairs.cfg"), 2));
  text += "light { position = (0, 10, 0); }\n";
  Scene scene = parseSceneText(text, "pairs.cfg");
  EXPECT_NO_THROW(checkLoopLimit(scene, 1));
  try {
    checkLoopLimit(scene, 2);
    ADD_FAILURE() << "no error for 121 lights and 264 objects, traced twice";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "pairs.cfg:385:1: the scene has 121 lights and 264 objects every ray tests: "
                                     "2 x ((lights + 1) x (objects + 3) + 111) = 65370 loop passes per edge pixel "
                                     "of the coverage filter, more than the 65000 the lavapipe driver runs");
  }
}

// Every material for the viewer, but no image file past the first MAX_IMAGES: a material whose
// image would be the 17th is left out (packed when an object takes it), not refused.
TEST(GpuScene, AllMaterialsLeavesOutImagesPastTheLimit) {
  std::string text = "material earth { texture = image { file = \"../../../textures/earth.jpg\"; } }\n";
  for (int i = 1; i <= MAX_IMAGES; ++i) {
    char name[16];
    snprintf(name, sizeof(name), "%02d", i);
    text += std::string("material m") + name + " { texture = image { file = \"count/" + name + ".png\"; } }\n";
  }
  text += "sphere { radius = 1; m16; }\n";
  Scene scene = parseSceneText(text, kSourceDir + "/tests/malformed/images/all.cfg");
  PackOptions pack;
  pack.mipmaps = false;
  pack.allMaterials = true;
  GpuScene g = buildGpuScene(scene, 8, 8, pack);
  ASSERT_EQ(g.images.size(), size_t(MAX_IMAGES));
  EXPECT_NE(g.images[0].path.find("count/16.png"), std::string::npos);  // the object's first
  EXPECT_EQ(g.materials.size(), size_t(MAX_IMAGES));
  // In order of definition: earth.jpg, count/01 .. count/14 fit; count/15.png would be the 17th.
  EXPECT_EQ(g.materialIndex.count(0), 1u);
  EXPECT_EQ(g.materialIndex.count(15), 0u);
  EXPECT_EQ(g.shape.imageCount, 1u);
  scene.spheres[0].material = 15;  // an object takes it: packed first
  g = buildGpuScene(scene, 8, 8, pack);
  EXPECT_EQ(g.materialIndex.at(15), 0u);
  EXPECT_NE(g.images[0].path.find("count/15.png"), std::string::npos);
}

TEST(GpuScene, AllMaterialsPacksUnusedOnesButSpecialisesToTheUsed) {
  Scene scene = parseSceneFile(kSourceDir + "/scenes/textures.cfg");
  PackOptions pack;
  pack.mipmaps = false;
  GpuScene used = buildGpuScene(scene, 8, 8, pack);
  pack.allMaterials = true;
  GpuScene all = buildGpuScene(scene, 8, 8, pack);
  EXPECT_EQ(used.materials.size(), 2u);
  EXPECT_EQ(all.materials.size(), scene.materials.size());
  EXPECT_EQ(all.shape, used.shape);
  EXPECT_EQ(all.imageChains.size(), 1u);  // anImage's earth.jpg, ready for a switch
  EXPECT_EQ(used.imageChains.size(), 0u);
}

// One function builds every kernel's key: the scene's shape, the render's options by name, and
// the scene's values only when asked for.
TEST(KernelKey, BuiltFromTheSceneAndTheOptions) {
  Scene scene = parseSceneText("sphere { radius = 1; }\nplane { normal = (0, 1, 0); distance = -1; }\n"
                               "light { position = (0, 5, 0); }\n",
                               "key.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  KernelOptions options;
  options.textureFilter = FILTER_BOX;
  options.samplesPerSide = 3;
  options.progressive = true;
  KernelKey key = kernelKey(g, options);
  EXPECT_EQ(key.shape, g.shape);
  EXPECT_EQ(key.textureFilter, uint32_t(FILTER_BOX));
  EXPECT_EQ(key.samplesPerSide, 3u);
  EXPECT_EQ(key.progressive, 1u);
  EXPECT_EQ(key.outputMode, uint32_t(OUTPUT_SHADED));
  EXPECT_EQ(key.baked.enabled, 0u);
  options.bakeValues = true;
  KernelKey baked = kernelKey(g, options);
  EXPECT_EQ(baked.baked, bakeScene(g));
  EXPECT_EQ(baked.baked.enabled, 1u);
  EXPECT_FALSE(baked == key);
}
