// Images at their own size (each its own texture and mip chain, BINDING_IMAGES) and
// `wrap = clamp`, rendered on a Vulkan device (lavapipe in CI) with validation on, against the
// float64 reference.
#include "support/gpu_fixture.h"
#include "image.h"
#include "atomic_file.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"
#include "support/files.h"
#include "support/reference_pixels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {


// Ambient light and ambient coefficient 1, no lights: every pixel is the texture colour.
std::string flatImage(const std::string& name, const std::string& file, const std::string& wrap = "repeat") {
  return "material " + name + " { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0);"
         " texture = image { file = \"" + file + "\"; wrap = " + wrap + "; }; }\n";
}

Scene sizeTestScene(const std::string& text) {
  return parseSceneText("ambient_light = (1, 1, 1);\nbackground = (0.5, 0.5, 0.5);\n" + text,
                        kSourceDir + "/scenes/image_size_test.cfg");
}

// The largest channel difference of two renders over the pixels in `mask`.
float maxDifference(const std::vector<float>& a, const std::vector<float>& b, const std::vector<bool>& mask) {
  float worst = 0.0f;
  for (size_t i = 0; i < mask.size(); ++i)
    for (int c = 0; mask[i] && c < 3; ++c) worst = std::max(worst, std::abs(a[i * 4 + c] - b[i * 4 + c]));
  return worst;
}

class ImageSizeTest : public RenderTest {};

// The test: uv_grid.png (512 x 256) on a sphere and on the floor renders to the same
// pixels, bit for bit, whether the second sphere shows earth.jpg (2048 x 1024) or a same-size
// copy of uv_grid.png; point and box. (On main's array of layers resized to the largest image,
// uv_grid.png was resampled to 2048 x 1024 next to earth.jpg: up to 152/255 off.)
TEST_F(ImageSizeTest, AnObjectsPixelsDoNotDependOnOtherImages) {
  fs::path dir = freshTempDir("image_size");
  fs::copy_file(kSourceDir + "/textures/uv_grid.png", dir / "uv_grid_copy.png");
  auto scene = [&](const std::string& other) {
    return sizeTestScene(flatImage("grid", "../textures/uv_grid.png") + flatImage("other", other) +
                         "camera { eye = (0, 1.5, 7); lookat = (0, 0, 0); up = (0, 1, 0); fov = 45; }\n"
                         "sphere { center = (-1.2, 0, 0); radius = 1; grid; }\n"
                         "sphere { center = (1.2, 0, 0); radius = 1; other; }\n"
                         "plane { normal = (0, 1, 0); distance = -1; tex_scale = 2; grid; }\n");
  };
  Scene withEarth = scene("../textures/earth.jpg"), withCopy = scene((dir / "uv_grid_copy.png").string());
  const int w = 160, h = 120;
  std::vector<bool> first = interiorMask(withEarth, w, h, [](const ReferenceHit& hit) {
    return hit.kind == HIT_PLANE || (hit.kind == HIT_SPHERE && hit.index == 0);
  });
  std::vector<bool> second = interiorMask(withEarth, w, h, [](const ReferenceHit& hit) {
    return hit.kind == HIT_SPHERE && hit.index == 1;
  });
  ASSERT_GT(std::count(first.begin(), first.end(), true), w * h / 4);
  ASSERT_GT(std::count(second.begin(), second.end(), true), w * h / 20);
  for (uint32_t filter : {FILTER_POINT, FILTER_BOX}) {
    SCOPED_TRACE(filter == FILTER_BOX ? "box" : "point");
    std::vector<float> a = render(withEarth, w, h, OUTPUT_SHADED, 1, filter);
    std::vector<float> b = render(withCopy, w, h, OUTPUT_SHADED, 1, filter);
    EXPECT_EQ(maxDifference(a, b, first), 0.0f);
    EXPECT_GT(maxDifference(a, b, second), 0.25f);  // the second sphere does show another image
  }
}

// GPU point render against the float64 reference (one sample at each pixel centre) over the
// pixels wholly on the objects: 8-bit texels and the driver's bilinear weights, within 0.02.
class WrapTest : public RenderTest {
 protected:
  double worstAgainstReference(const Scene& scene, int w, int h) {
    std::vector<bool> mask = interiorMask(scene, w, h, [](const ReferenceHit& hit) { return hit.kind != 0; });
    EXPECT_GT(std::count(mask.begin(), mask.end(), true), w * h / 4);
    ReferenceImage ref = renderReference(scene, w, h, 1);
    std::vector<float> gpu = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT);
    double worst = 0.0;
    for (size_t i = 0; i < mask.size(); ++i)
      for (int c = 0; mask[i] && c < 3; ++c) worst = std::max(worst, std::abs(double(gpu[i * 4 + c]) - ref.rgb[i * 3 + c]));
    return worst;
  }
};

// wrap = clamp on the floor: the image once, in the tile whose unwrapped coordinate lies in
// [0, 1], its edge texels beyond (CLAMP_TO_EDGE); the same 4096 tiles away, where the kernel's
// tile index reduced mod 4096 would be 0 again (the host packs the exact tile for clamp).
TEST_F(WrapTest, ClampShowsTheImageOnceOnAPlane) {
  const std::string floor = flatImage("decal", "../textures/uv_grid.png", "clamp") +
                            "plane { normal = (0, 1, 0); distance = 0; tex_scale = 2; decal; }\n";
  Scene nearDecal = sizeTestScene(floor + "camera { eye = (1, 4, 6); lookat = (1, 0, 1); up = (0, 1, 0); fov = 60; }\n");
  EXPECT_LT(worstAgainstReference(nearDecal, 128, 96), 0.02);
  // Tile (4096, 0) and its neighbours: every texel there is an edge texel of the image.
  Scene farTile = sizeTestScene(floor + "camera { eye = (8193, 3, 1); lookat = (8193, 0, 0.9); up = (0, 1, 0); fov = 60; }\n");
  EXPECT_LT(worstAgainstReference(farTile, 128, 96), 0.02);
  // And the same with wrap = repeat (default) there: the image, tiled.
  Scene repeated = sizeTestScene(flatImage("tiled", "../textures/uv_grid.png") +
                                 "plane { normal = (0, 1, 0); distance = 0; tex_scale = 2; tiled; }\n"
                                 "camera { eye = (8193, 3, 1); lookat = (8193, 0, 0.9); up = (0, 1, 0); fov = 60; }\n");
  EXPECT_LT(worstAgainstReference(repeated, 128, 96), 0.02);
}

// wrap = clamp on a sphere: v as always, and u clamped too: at the seam (the -x meridian) the
// first (red) and last (blue) columns of a 4 x 2 image are not blended.
TEST_F(WrapTest, ClampDoesNotWrapAcrossASpheresSeam) {
  fs::path dir = freshTempDir("wrap_seam");
  ImageRGBA8 columns{4, 2, {}};
  for (int y = 0; y < 2; ++y)
    for (uint8_t c : {255, 0, 0, 255, 0, 255, 0, 255, 255, 255, 255, 255, 0, 0, 255, 255}) columns.pixels.push_back(c);
  ASSERT_NO_THROW(writePngAtomic((dir / "columns.png").string(), columns));
  Scene scene = sizeTestScene(flatImage("decal", (dir / "columns.png").string(), "clamp") +
                              "camera { eye = (-4, 0.5, 0); lookat = (0, 0, 0); up = (0, 1, 0); fov = 40; }\n"
                              "sphere { center = (0, 0, 0); radius = 1; decal; }\n");
  EXPECT_LT(worstAgainstReference(scene, 96, 96), 0.02);
}

}  // namespace
