// Image measures (host/compare/image_metrics.h) and the linear image reader (host/image/image_file.h): RMSE
// and PSNR against values worked by hand, SSIM against a plain double computation written
// here and against scikit-image's values, the threshold share on a constructed pair, and the
// clamping of low-dynamic-range inputs.
#include "cli.h"
#include "float_memo.h"
#include "image_file.h"
#include "srgb.h"
#include "image_metrics.h"
#include "output_formats.h"
#include "atomic_file.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

namespace {

FloatImage blank(int w, int h, float value = 0.0f) {
  FloatImage image;
  image.width = w;
  image.height = h;
  image.channels = 3;
  image.pixels.assign(size_t(w) * h * 3, value);
  return image;
}

void set(FloatImage& image, int x, int y, float r, float g, float b) {
  float* p = &image.pixels[(size_t(y) * image.width + x) * 3];
  p[0] = r;
  p[1] = g;
  p[2] = b;
}

FloatImage randomImage(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  FloatImage image = blank(w, h);
  for (float& v : image.pixels) v = u(rng);
  return image;
}

// SSIM the textbook way: for every 7x7 window wholly inside, the means, the sample variances
// and covariance from the deviations (divided by N - 1), the formula of Wang et al. with
// C1 = (0.01)^2 and C2 = (0.03)^2; the mean over windows and channels.
double plainSsim(const FloatImage& a, const FloatImage& b) {
  double total = 0.0;
  int count = 0;
  for (int c = 0; c < 3; ++c)
    for (int y0 = 0; y0 + 7 <= a.height; ++y0)
      for (int x0 = 0; x0 + 7 <= a.width; ++x0) {
        double mx = 0, my = 0;
        for (int y = y0; y < y0 + 7; ++y)
          for (int x = x0; x < x0 + 7; ++x) {
            mx += a.at(x, y, c) / 49.0;
            my += b.at(x, y, c) / 49.0;
          }
        double vx = 0, vy = 0, cxy = 0;
        for (int y = y0; y < y0 + 7; ++y)
          for (int x = x0; x < x0 + 7; ++x) {
            const double dx = a.at(x, y, c) - mx, dy = b.at(x, y, c) - my;
            vx += dx * dx / 48.0;
            vy += dy * dy / 48.0;
            cxy += dx * dy / 48.0;
          }
        const double c1 = 1e-4, c2 = 9e-4;
        total += (2 * mx * my + c1) * (2 * cxy + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
        ++count;
      }
  return total / count;
}

TEST(ImageMetrics, RmseAndPsnrOfAWorkedExample) {
  FloatImage a = blank(2, 1), b = blank(2, 1);
  set(b, 1, 0, 0.1f, 0.2f, 0.3f);
  // Six channel differences, squares 0.01 + 0.04 + 0.09 = 0.14: MSE 0.14 / 6 = 0.0233333,
  // RMSE 0.1527525, PSNR 10 log10(1 / 0.0233333) = 16.3202 dB.
  EXPECT_NEAR(rootMeanSquareError(a, b), 0.1527525, 1e-6);
  EXPECT_NEAR(peakSignalToNoise(rootMeanSquareError(a, b)), 16.3202, 1e-4);
  EXPECT_NEAR(peakSignalToNoise(0.1), 20.0, 1e-12);
  EXPECT_EQ(rootMeanSquareError(a, a), 0.0);
  EXPECT_TRUE(std::isinf(peakSignalToNoise(0.0)));
}

TEST(ImageMetrics, RmseOverTheMaskedPixelsOfRgbaFrames) {
  // Two 3x1 RGBA frames: alpha is not a colour channel; pixel 1 differs by 0.3 in red and
  // pixel 2 by 0.6 in blue. Over pixels 1 and 2: sqrt((0.09 + 0.36) / 6) = 0.2738613.
  const float a[12] = {0, 0, 0, 1, 0.5f, 0.5f, 0.5f, 1, 0.1f, 0.2f, 0.3f, 1};
  const float b[12] = {0, 0, 0, 0, 0.8f, 0.5f, 0.5f, 1, 0.1f, 0.2f, 0.9f, 0};
  const FloatImage fa = rgbaFloatImage(a, 3, 1), fb = rgbaFloatImage(b, 3, 1);
  EXPECT_EQ(fa.channels, 4);
  EXPECT_EQ(fa.at(2, 0, 2), 0.3f);
  const std::vector<bool> last2 = {false, true, true}, first = {true, false, false}, none(3, false);
  EXPECT_NEAR(rootMeanSquareError(fa, fb, &last2), 0.2738613, 1e-6);
  EXPECT_NEAR(rootMeanSquareError(fa, fb), std::sqrt(0.45 / 9), 1e-7);
  EXPECT_EQ(rootMeanSquareError(fa, fb, &first), 0.0);
  EXPECT_EQ(rootMeanSquareError(fa, fb, &none), 0.0);
}

TEST(ImageMetrics, SsimEqualsAPlainComputation) {
  const FloatImage a = randomImage(20, 15, 1);
  FloatImage b = a;
  std::mt19937 rng(2);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  for (float& v : b.pixels) v = std::clamp(v + noise(rng), 0.0f, 1.0f);
  EXPECT_NEAR(structuralSimilarity(a, b), plainSsim(a, b), 1e-10);
  const FloatImage c = randomImage(20, 15, 3);
  EXPECT_NEAR(structuralSimilarity(a, c), plainSsim(a, c), 1e-10);
  EXPECT_LT(structuralSimilarity(a, c), 0.2);  // unrelated noise
}

TEST(ImageMetrics, SsimOfIdenticalImagesIsOne) {
  const FloatImage a = randomImage(31, 9, 4);
  EXPECT_DOUBLE_EQ(structuralSimilarity(a, a), 1.0);
  EXPECT_DOUBLE_EQ(structuralSimilarity(blank(7, 7, 0.3f), blank(7, 7, 0.3f)), 1.0);
  EXPECT_TRUE(std::isnan(structuralSimilarity(blank(6, 20), blank(6, 20))));  // no whole window
}

// scikit-image 0.19.3's structural_similarity(a, b, channel_axis=2, data_range=1.0) on the PNGs
// read as values / 255 (matplotlib), printed to 10 decimals.
TEST(ImageMetrics, SsimMatchesScikitImage) {
  const struct {
    const char* name;
    double ssim;
  } pairs[] = {{"course", 0.7872813779}, {"colour", 0.8075292158}, {"edges", 0.5193424345}};
  for (const auto& p : pairs) {
    const std::string dir = kSourceDir + "/tests/golden/flip/";
    const LinearImage a = readLinearImage(dir + p.name + "_a.png", 1u << 30);
    const LinearImage b = readLinearImage(dir + p.name + "_b.png", 1u << 30);
    EXPECT_NEAR(structuralSimilarity(linearToSrgbImage(a.image), linearToSrgbImage(b.image)), p.ssim, 1e-6)
        << p.name;
  }
}

TEST(ImageMetrics, MaxDifferenceAndShareOverThreshold) {
  FloatImage a = blank(4, 1, 0.5f), b = blank(4, 1, 0.5f);
  set(b, 1, 0, 0.5f, 0.505f, 0.5f);  // under 0.01
  set(b, 2, 0, 0.5f, 0.5f, 0.48f);   // 0.02 in one channel: over
  set(b, 3, 0, 0.0f, 1.0f, 0.5f);    // 0.5: over
  EXPECT_NEAR(maxChannelDifference(a, b), 0.5, 1e-7);
  EXPECT_NEAR(shareOverThreshold(a, b, 0.01), 0.5, 1e-12);
  EXPECT_NEAR(shareOverThreshold(a, b, 0.001), 0.75, 1e-12);
  EXPECT_EQ(shareOverThreshold(a, b, 0.5), 0.0);  // over, not at
  EXPECT_EQ(shareOverThreshold(a, a, 0.0), 0.0);
}

TEST(ImageMetrics, DefaultThresholdIsAboveEveryEightBitStep) {
  double widest = 0.0;
  for (int i = 0; i < 255; ++i) widest = std::max(widest, srgbToLinear((i + 1) / 255.0) - srgbToLinear(i / 255.0));
  EXPECT_NEAR(widest, 1.0 - srgbToLinear(254 / 255.0), 1e-12);
  EXPECT_GT(kDefaultDiffThreshold, widest);
  EXPECT_LT(kDefaultDiffThreshold, 2 * widest);
}

TEST(ImageMetrics, LowDynamicRangeClampsBoth) {
  LinearImage ldr{blank(2, 2, 1.0f), true};
  LinearImage hdr{blank(2, 2, 3.0f), false};
  hdr.image.pixels[0] = -0.5f;
  ldr.image.pixels[0] = 0.0f;
  clampForComparison(ldr, hdr);
  EXPECT_EQ(rootMeanSquareError(ldr.image, hdr.image), 0.0);

  LinearImage hdrA{blank(2, 2, 1.0f), false}, hdrB{blank(2, 2, 3.0f), false};
  clampForComparison(hdrA, hdrB);
  EXPECT_NEAR(rootMeanSquareError(hdrA.image, hdrB.image), 2.0, 1e-12);
}

TEST(ImageMetrics, LinearToSrgbClampsAndEncodes) {
  FloatImage linear = blank(4, 1);
  set(linear, 0, 0, 0.2140411f, 0.0f, 1.0f);
  set(linear, 1, 0, 2.0f, -1.0f, NAN);
  const FloatImage srgb = linearToSrgbImage(linear);
  EXPECT_NEAR(srgb.at(0, 0, 0), 0.5, 1e-6);
  EXPECT_EQ(srgb.at(0, 0, 1), 0.0f);
  EXPECT_NEAR(srgb.at(0, 0, 2), 1.0, 1e-6);
  EXPECT_NEAR(srgb.at(1, 0, 0), 1.0, 1e-6);
  EXPECT_EQ(srgb.at(1, 0, 1), 0.0f);
  EXPECT_EQ(srgb.at(1, 0, 2), 0.0f);
}

TEST(ImageMetrics, LinearToSrgbRowIsARowOfTheImage) {
  FloatImage linear = randomImage(5, 3, 9);
  set(linear, 1, 1, 2.0f, -1.0f, NAN);
  set(linear, 4, 2, INFINITY, 1e-9f, 0.0031308f);
  for (int channels : {3, 4}) {
    FloatImage image = linear;
    if (channels == 4) {  // alpha after each pixel's colour: not encoded, not in the row
      image.channels = 4;
      image.pixels.clear();
      for (size_t i = 0; i < linear.pixels.size(); i += 3)
        image.pixels.insert(image.pixels.end(), {linear.pixels[i], linear.pixels[i + 1], linear.pixels[i + 2], 0.5f});
    }
    const FloatImage srgb = linearToSrgbImage(image);
    std::vector<float> row(size_t(image.width) * 3);
    for (int y = 0; y < image.height; ++y)
      for (auto [x0, x1] : {std::pair{0, 5}, std::pair{1, 4}, std::pair{3, 5}}) {
        linearToSrgbRow(image, y, x0, x1, row.data());
        for (int x = x0; x < x1; ++x)
          for (int c = 0; c < 3; ++c)
            EXPECT_EQ(row[size_t(x - x0) * 3 + size_t(c)], srgb.at(x, y, c)) << x << "," << y;
      }
  }
}

double plusOne(float v) { return double(v) + 1.0; }

// Every result the memo gives is the function's, through collisions (more values than
// entries), repeats, NaN (its start key among them), infinities and signed zeros.
TEST(FloatMemo, GivesTheFunctionsResultsToTheBit) {
  FloatMemo<double, plusOne> memo;
  std::mt19937 rng(3);
  std::uniform_int_distribution<uint32_t> bits(0, 0xffffffffu);
  std::vector<float> values = {0.0f, -0.0f, INFINITY, -INFINITY, NAN, 1.0f};
  for (uint32_t key : {0x7fc00001u, 0x7fc00000u, 0xffc00001u}) {
    float v;
    std::memcpy(&v, &key, sizeof v);
    values.push_back(v);
  }
  for (int i = 0; i < 20000; ++i) {
    const uint32_t b = bits(rng);
    float v;
    std::memcpy(&v, &b, sizeof v);
    values.push_back(v);
  }
  for (int round = 0; round < 2; ++round)
    for (float v : values) {
      const double got = memo(v), want = plusOne(v);
      EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0) << v;
    }
}

TEST(ImageMetrics, MeasureImagesGathersEveryMeasure) {
  const FloatImage a = randomImage(12, 10, 5), b = randomImage(12, 10, 6);
  const ImageMetrics m = measureImages(a, b, 0.25);
  EXPECT_EQ(m.rmse, rootMeanSquareError(a, b));
  EXPECT_EQ(m.psnr, peakSignalToNoise(m.rmse));
  EXPECT_EQ(m.ssim, structuralSimilarity(linearToSrgbImage(a), linearToSrgbImage(b)));
  EXPECT_EQ(m.maxDifference, maxChannelDifference(a, b));
  EXPECT_EQ(m.shareOver, shareOverThreshold(a, b, 0.25));
}

TEST(ImageRead, PngIsDecodedToLinear) {
  const std::filesystem::path dir = freshTempDir("image_read");
  ImageRGBA8 png{3, 1, {0, 128, 255, 255, 10, 20, 30, 255, 255, 255, 255, 0}};
  writePngAtomic((dir / "a.png").string(), png);
  const LinearImage image = readLinearImage((dir / "a.png").string(), 1024);
  EXPECT_TRUE(image.lowDynamicRange);
  ASSERT_EQ(image.image.channels, 3);
  ASSERT_EQ(image.image.width, 3);
  EXPECT_EQ(image.image.at(0, 0, 0), 0.0f);
  EXPECT_NEAR(image.image.at(0, 0, 1), srgbToLinear(128 / 255.0), 1e-7);
  EXPECT_NEAR(image.image.at(1, 0, 2), srgbToLinear(30 / 255.0), 1e-7);
  EXPECT_EQ(image.image.at(2, 0, 0), 1.0f);
}

TEST(ImageRead, PfmIsReadAsStoredOfHighDynamicRange) {
  const std::filesystem::path dir = freshTempDir("image_read_pfm");
  // 2x1, little-endian (negative scale), rows from the bottom: one row, so no flip to mind.
  const float values[6] = {2.5f, 0.25f, -1.0f, 0.0f, 1.0f, 100.0f};
  std::string bytes = "PF\n2 1\n-1.0\n";
  bytes.append(reinterpret_cast<const char*>(values), sizeof values);
  writeFile(dir / "a.pfm", bytes);
  const LinearImage image = readLinearImage((dir / "a.pfm").string(), 1024);
  EXPECT_FALSE(image.lowDynamicRange);
  ASSERT_EQ(image.image.width, 2);
  ASSERT_EQ(image.image.channels, 3);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(image.image.pixels[size_t(i)], values[i]);
}

TEST(ImageMetrics, CountsValuesThatAreNotFinite) {
  FloatImage image = blank(3, 1, 0.5f);
  set(image, 0, 0, NAN, 0.5f, INFINITY);
  set(image, 2, 0, 0.5f, -INFINITY, 0.5f);
  EXPECT_EQ(nonFiniteCount(image), 3u);
  EXPECT_EQ(nonFiniteCount(blank(3, 1, 1e30f)), 0u);
}

TEST(ImageRead, RefusesWhatItCannotRead) {
  const std::filesystem::path dir = freshTempDir("image_read_refuses");
  writePngAtomic((dir / "a.png").string(), ImageRGBA8{4, 4, std::vector<uint8_t>(64, 200)});
  writeFile(dir / "b.exr", "v/1\x01");
  writeFile(dir / "c.pfm", "PF\n1 1\n-1.0\n");
  auto message = [](const std::string& path, uint64_t budget) {
    try {
      readLinearImage(path, budget);
    } catch (const ImageInputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message((dir / "a.png").string(), 4 * 4 * 12 - 1).find("MiB allowed"), std::string::npos);
  EXPECT_EQ(message((dir / "a.png").string(), 4 * 4 * 12), "no error");
  EXPECT_NE(message((dir / "b.exr").string(), 1024).find((dir / "b.exr").string()), std::string::npos);
  EXPECT_NE(message((dir / "c.pfm").string(), 1024).find((dir / "c.pfm").string()), std::string::npos);
  EXPECT_NE(message((dir / "none.png").string(), 1024).find((dir / "none.png").string()), std::string::npos);
}

}  // namespace
