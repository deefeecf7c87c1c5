#include "image_file.h"
#include "srgb.h"
#include "atomic_file.h"
#include "support/files.h"
#include "support/image_diff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

TEST(ImageIo, SrgbTransferFunctionRoundTrips) {
  // Reference points of the sRGB curve (IEC 61966-2-1).
  EXPECT_NEAR(linearToSrgb(0.0), 0.0, 1e-12);
  EXPECT_NEAR(linearToSrgb(1.0), 1.0, 1e-12);
  EXPECT_NEAR(linearToSrgb(0.18), 0.4613561, 1e-6);
  EXPECT_NEAR(srgbToLinear(0.5), 0.2140411, 1e-6);
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(srgbToLinear(linearToSrgb(i / 100.0)), i / 100.0, 1e-12);
}

TEST(ImageIo, EncodeSrgbMatchesFormulaClampsAndCountsNonFinite) {
  std::vector<float> px;
  for (int i = 0; i < 256; ++i) px.insert(px.end(), {i / 255.0f, 0.0f, 1.0f, 1.0f});
  px.insert(px.end(), {-1.0f, 2.0f, NAN, 1.0f});
  px.insert(px.end(), {INFINITY, 0.5f, 0.5f, 1.0f});
  size_t bad = 0;
  ImageRGBA8 img = encodeSrgb(px.data(), 258, 1, &bad);
  for (int i = 0; i < 256; ++i) {
    int exact = int(std::lround(linearToSrgb(i / 255.0) * 255.0));
    EXPECT_NEAR(img.pixels[i * 4], exact, 1) << i;
    EXPECT_EQ(img.pixels[i * 4 + 2], 255);
    EXPECT_EQ(img.pixels[i * 4 + 3], 255);
  }
  EXPECT_EQ(img.pixels[256 * 4 + 0], 0);    // clamped below
  EXPECT_EQ(img.pixels[256 * 4 + 1], 255);  // clamped above
  EXPECT_EQ(img.pixels[256 * 4 + 2], 0);    // NaN -> 0
  EXPECT_EQ(bad, 2u);
}

TEST(ImageIo, WritesPngThatDecodesToTheSamePixels) {
  fs::path dir = freshTempDir("image_io_roundtrip");
  ImageRGBA8 img;
  img.width = 7;
  img.height = 5;
  for (int i = 0; i < 35; ++i) img.pixels.insert(img.pixels.end(), {uint8_t(i * 7), uint8_t(255 - i), uint8_t(i), 255});
  std::string path = (dir / "a.png").string();
  writePngAtomic(path, img);
  ImageRGBA8 back;
  std::string error;
  ASSERT_NO_THROW(back = loadImage(path));
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.pixels, img.pixels);
  ImageDiff diff = compareImages(img, back);
  EXPECT_EQ(diff.maxError, 0);
  // Only the PNG is left: the temporary file was renamed.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(ImageIo, FailedWriteLeavesNoFileAndNamesThePath) {
  ImageRGBA8 img;
  img.width = img.height = 1;
  img.pixels = {1, 2, 3, 255};
  try {
    writePngAtomic("/nonexistent-dir/x.png", img);
    FAIL() << "expected an exception";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.png"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists("/nonexistent-dir/x.png"));
}

TEST(ImageIo, LoadReportsMissingAndUndecodableFiles) {
  fs::path dir = freshTempDir("image_io_load");
  auto loadError = [](const fs::path& path) {
    try {
      loadImage(path.string());
    } catch (const ImageInputError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(loadError(dir / "missing.png").find("cannot open"), std::string::npos);
  std::ofstream((dir / "bad.png").string()) << "not an image";
  EXPECT_NE(loadError(dir / "bad.png").find("cannot decode"), std::string::npos);
}

TEST(ImageIo, CompareAndDiffImages) {
  ImageRGBA8 a, b;
  a.width = b.width = 2;
  a.height = b.height = 1;
  a.pixels = {10, 10, 10, 255, 0, 0, 0, 255};
  b.pixels = {10, 13, 10, 255, 0, 0, 9, 255};
  ImageDiff d = compareImages(a, b);
  EXPECT_EQ(d.maxError, 9);
  EXPECT_DOUBLE_EQ(d.meanError, 12.0 / 6.0);
  ImageRGBA8 diff = diffImage(a, b, 2);
  EXPECT_EQ(diff.pixels[1], 6);
  EXPECT_EQ(diff.pixels[6], 18);
  b.width = 1;
  EXPECT_TRUE(compareImages(a, b).sizeMismatch);
}

TEST(ImageIo, ResizeKeepsAUniformColour) {
  ImageRGBA8 img;
  img.width = 4;
  img.height = 2;
  for (int i = 0; i < 8; ++i) img.pixels.insert(img.pixels.end(), {200, 100, 50, 255});
  ImageRGBA8 r = resizeImage(img, 8, 4);
  ASSERT_EQ(r.pixels.size(), 8u * 4 * 4);
  for (size_t i = 0; i < r.pixels.size(); i += 4) {
    EXPECT_NEAR(r.pixels[i], 200, 1);
    EXPECT_NEAR(r.pixels[i + 1], 100, 1);
    EXPECT_NEAR(r.pixels[i + 2], 50, 1);
  }
}

}  // namespace
