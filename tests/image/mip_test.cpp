// Mip chains of image textures (host/image/mip_chain.h, mipChain): sizes, linear-light averaging,
// the 1x1 last level, and their packing for the GPU (buildGpuScene). No Vulkan device.
#include "gpu_scene.h"
#include "image_file.h"
#include "mip_chain.h"
#include "srgb.h"
#include "parser.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace {


ImageRGBA8 solidImage(int w, int h, uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255) {
  ImageRGBA8 img;
  img.width = w;
  img.height = h;
  for (int i = 0; i < w * h; ++i) img.pixels.insert(img.pixels.end(), {r, g, b, a});
  return img;
}

// Texel-sized checker of two colours.
ImageRGBA8 checkerImage(int w, int h, const uint8_t a[3], const uint8_t b[3]) {
  ImageRGBA8 img;
  img.width = w;
  img.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* c = ((x + y) & 1) ? b : a;
      img.pixels.insert(img.pixels.end(), {c[0], c[1], c[2], 255});
    }
  return img;
}

int code(double linear) { return int(std::lround(linearToSrgb(linear) * 255.0)); }
double decode(int code) { return srgbToLinear(code / 255.0); }

TEST(MipChain, LevelCountAndSizesFollowVulkan) {
  EXPECT_EQ(mipLevelCount(1, 1), 1);
  EXPECT_EQ(mipLevelCount(2, 1), 2);
  EXPECT_EQ(mipLevelCount(512, 256), 10);
  EXPECT_EQ(mipLevelCount(2048, 1024), 12);
  EXPECT_EQ(mipLevelCount(5, 3), 3);
  EXPECT_EQ(mipLevelCount(1000, 7), 10);

  // Level i is max(1, w >> i) x max(1, h >> i): power-of-two, non-power-of-two, thin.
  const std::pair<int, int> sizes[] = {{8, 4}, {5, 3}, {7, 7}, {1000, 7}, {1, 9}, {1, 1}};
  for (auto [w, h] : sizes) {
    std::vector<ImageRGBA8> chain = mipChain(solidImage(w, h, 10, 20, 30));
    ASSERT_EQ(int(chain.size()), mipLevelCount(w, h)) << w << "x" << h;
    for (size_t i = 0; i < chain.size(); ++i) {
      EXPECT_EQ(chain[i].width, std::max(1, w >> i)) << w << "x" << h << " level " << i;
      EXPECT_EQ(chain[i].height, std::max(1, h >> i)) << w << "x" << h << " level " << i;
      EXPECT_EQ(chain[i].pixels.size(), size_t(chain[i].width) * chain[i].height * 4);
    }
    EXPECT_EQ(chain.back().width, 1);
    EXPECT_EQ(chain.back().height, 1);
  }
}

TEST(MipChain, LevelZeroIsTheImageAndConstantImagesStayConstant) {
  ImageRGBA8 img = solidImage(6, 10, 200, 17, 90, 128);
  img.pixels[5] = 99;  // one different texel: level 0 must be the image itself
  std::vector<ImageRGBA8> chain = mipChain(img);
  EXPECT_EQ(chain[0].pixels, img.pixels);
  std::vector<ImageRGBA8> flat = mipChain(solidImage(6, 10, 200, 17, 90, 128));
  for (const ImageRGBA8& level : flat)
    for (size_t i = 0; i < level.pixels.size(); i += 4) {
      EXPECT_EQ(level.pixels[i], 200);
      EXPECT_EQ(level.pixels[i + 1], 17);
      EXPECT_EQ(level.pixels[i + 2], 90);
      EXPECT_EQ(level.pixels[i + 3], 128);  // alpha averaged linearly, unchanged here
    }
}

// Black/white (and a colour pair) checker: every level above 0 is the mean in LINEAR light,
// re-encoded (white+black -> code 188, not the sRGB mean 128), for even and odd sizes.
TEST(MipChain, CoarseLevelsAverageInLinearLight) {
  const uint8_t black[3] = {0, 0, 0}, white[3] = {255, 255, 255};
  const uint8_t red[3] = {230, 40, 10}, blue[3] = {20, 90, 250};
  int linearMean = code(0.5);
  ASSERT_EQ(linearMean, 188);
  for (auto [w, h] : {std::pair<int, int>{64, 32}, {16, 16}}) {
    std::vector<ImageRGBA8> chain = mipChain(checkerImage(w, h, black, white));
    for (size_t i = 1; i < chain.size(); ++i)
      for (size_t p = 0; p < chain[i].pixels.size(); p += 4)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(chain[i].pixels[p + c], linearMean) << "level " << i;
  }
  std::vector<ImageRGBA8> chain = mipChain(checkerImage(32, 32, red, blue));
  for (size_t i = 1; i < chain.size(); ++i)
    for (size_t p = 0; p < chain[i].pixels.size(); p += 4)
      for (int c = 0; c < 3; ++c) {
        int expected = code(0.5 * (decode(red[c]) + decode(blue[c])));
        int srgbMean = (red[c] + blue[c]) / 2;
        ASSERT_EQ(chain[i].pixels[p + c], expected) << "level " << i << " channel " << c;
        if (std::abs(expected - srgbMean) > 2) {
          ASSERT_NE(chain[i].pixels[p + c], srgbMean);
        }
      }

  // Odd size: a 5x5 checker has 13 black and 12 white texels; the 1x1 level is their exact
  // linear mean (fractional weights at the odd edges still sum each texel once overall).
  chain = mipChain(checkerImage(5, 5, white, black));
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(chain[2].pixels[0], code(13.0 / 25.0));
  // Level 1 (2x2): each texel covers 2.5 x 2.5 source texels, partly covering the middle row
  // and column: compare with the area average found by point sampling a 400 x 400 grid.
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      double sum = 0.0;
      for (int j = 0; j < 400; ++j)
        for (int i = 0; i < 400; ++i) {
          int sx = int((tx + (i + 0.5) / 400.0) * 2.5), sy = int((ty + (j + 0.5) / 400.0) * 2.5);
          sum += ((sx + sy) & 1) ? 0.0 : 1.0;
        }
      // Texel (0, 0) holds 3.25 of 6.25 white texels: 0.52, code 191 (0.5 would be 188).
      EXPECT_EQ(chain[1].pixels[size_t(ty * 2 + tx) * 4], code(sum / 160000.0)) << tx << "," << ty;
    }
  EXPECT_EQ(chain[1].pixels[0], 191);
}

// The last level is the linear mean of the whole image (here two halves of different colour).
TEST(MipChain, LastLevelIsTheLinearMeanOfTheImage) {
  for (auto [w, h] : {std::pair<int, int>{512, 256}, {300, 200}, {7, 3}}) {
    ImageRGBA8 img = solidImage(w, h, 0, 0, 0);
    double sum[3] = {0, 0, 0};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        uint8_t* p = &img.pixels[(size_t(y) * w + x) * 4];
        p[0] = uint8_t((x * 7 + y * 3) & 255);
        p[1] = uint8_t(x < w / 2 ? 255 : 30);
        p[2] = uint8_t((x * y) & 255);
        for (int c = 0; c < 3; ++c) sum[c] += decode(p[c]);
      }
    std::vector<ImageRGBA8> chain = mipChain(img);
    const ImageRGBA8& last = chain.back();
    ASSERT_EQ(last.width * last.height, 1);
    // Float accumulation over ~12 levels: within one code value of the exact mean.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(last.pixels[c], code(sum[c] / (double(w) * h)), 1) << w << "x" << h;
  }
}

// buildGpuScene packs each image's own chain: level 0 as decoded, then its levels (mipChain),
// at the image's own size (uv_grid.png is not resampled to earth.jpg's 2048 x 1024).
TEST(MipChain, GpuScenePacksEachImagesOwnChain) {
  Scene scene = parseSceneText(
      "material a { texture = image { file = \"../textures/earth.jpg\"; }; }\n"
      "material b { texture = image { file = \"../textures/uv_grid.png\"; }; }\n"
      "sphere { center = (0, 0, 0); radius = 1; a; }\n"
      "sphere { center = (3, 0, 0); radius = 1; b; }\n",
      kSourceDir + "/scenes/mip_test.cfg");
  GpuScene g = buildGpuScene(scene, 8, 8);
  ASSERT_EQ(g.imageChains.size(), 2u);
  const int sizes[2][3] = {{2048, 1024, 12}, {512, 256, 10}};
  const char* files[2] = {"earth.jpg", "uv_grid.png"};
  for (size_t i = 0; i < 2; ++i) {
    const ImageChain& chain = g.imageChains[i];
    EXPECT_EQ(chain.width, sizes[i][0]);
    EXPECT_EQ(chain.height, sizes[i][1]);
    ASSERT_EQ(chain.levels, sizes[i][2]);
    ImageRGBA8 image;
    ASSERT_NO_THROW(image = loadImage(kSourceDir + "/textures/" + files[i]));
    std::vector<uint8_t> expected;
    for (const ImageRGBA8& level : mipChain(image)) expected.insert(expected.end(), level.pixels.begin(), level.pixels.end());
    EXPECT_TRUE(expected == chain.pixels) << files[i];
    EXPECT_EQ(g.materials[i].imageIndex, uint32_t(i) | uint32_t(sizes[i][2]) << 8);
    EXPECT_EQ(g.materials[i].imageSize, uint32_t(sizes[i][0]) | uint32_t(sizes[i][1]) << 16);
  }
}

}  // namespace
