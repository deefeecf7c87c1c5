#include "image_metrics.h"

#include "error.h"
#include "image_io.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace {

int colorChannels(const FloatImage& image) { return std::min(3, image.channels); }

void requireComparable(const FloatImage& a, const FloatImage& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error(ErrorKind::Internal, "images compared differ in size or channels: " + std::to_string(a.width) + "x" +
                                         std::to_string(a.height) + "x" + std::to_string(a.channels) + " and " +
                                         std::to_string(b.width) + "x" + std::to_string(b.height) + "x" +
                                         std::to_string(b.channels));
}

size_t pixelCount(const FloatImage& image) { return size_t(image.width) * size_t(image.height); }

// The largest colour-channel difference of pixel i.
double pixelDifference(const FloatImage& a, const FloatImage& b, size_t i) {
  double d = 0.0;
  for (int c = 0; c < colorChannels(a); ++c) {
    const size_t k = i * size_t(a.channels) + size_t(c);
    d = std::max(d, std::abs(double(a.pixels[k]) - double(b.pixels[k])));
  }
  return d;
}

// The five sums of SSIM (x, y, x^2, y^2, xy) of channel c over every run of kSsimWindow pixels
// along x: for each row, (width - kSsimWindow + 1) sums of each.
std::array<std::vector<double>, 5> rowWindowSums(const FloatImage& a, const FloatImage& b, int c) {
  const int w = a.width, h = a.height, ow = w - kSsimWindow + 1;
  std::array<std::vector<double>, 5> sums;
  for (std::vector<double>& s : sums) s.assign(size_t(ow) * size_t(h), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < ow; ++x) {
      const size_t out = size_t(y) * size_t(ow) + size_t(x);
      for (int k = 0; k < kSsimWindow; ++k) {
        const double u = a.at(x + k, y, c), v = b.at(x + k, y, c);
        sums[0][out] += u;
        sums[1][out] += v;
        sums[2][out] += u * u;
        sums[3][out] += v * v;
        sums[4][out] += u * v;
      }
    }
  return sums;
}

// The structural similarity of one window from its means of x, y, x^2, y^2 and xy, with
// sample (N - 1) variances and covariance.
double windowSsim(double ux, double uy, double uxx, double uyy, double uxy) {
  const double np = kSsimWindow * kSsimWindow, covNorm = np / (np - 1.0);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  const double vx = covNorm * (uxx - ux * ux), vy = covNorm * (uyy - uy * uy), vxy = covNorm * (uxy - ux * uy);
  return (2.0 * ux * uy + c1) * (2.0 * vxy + c2) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
}

// The sum of the structural similarity over the windows of channel c: the row sums added
// along y, one row of windows at a time.
double channelSsimSum(const FloatImage& a, const FloatImage& b, int c) {
  const std::array<std::vector<double>, 5> rows = rowWindowSums(a, b, c);
  const size_t ow = size_t(a.width - kSsimWindow + 1), oh = size_t(a.height - kSsimWindow + 1);
  const double np = kSsimWindow * kSsimWindow;
  std::array<std::vector<double>, 5> means;
  double sum = 0.0;
  for (size_t y = 0; y < oh; ++y) {
    for (size_t q = 0; q < 5; ++q) {
      means[q].assign(ow, 0.0);
      for (size_t k = 0; k < size_t(kSsimWindow); ++k)
        for (size_t x = 0; x < ow; ++x) means[q][x] += rows[q][(y + k) * ow + x];
      for (double& m : means[q]) m /= np;
    }
    for (size_t x = 0; x < ow; ++x) sum += windowSsim(means[0][x], means[1][x], means[2][x], means[3][x], means[4][x]);
  }
  return sum;
}

void clampToUnit(FloatImage& image) {
  for (float& v : image.pixels) v = std::clamp(v, 0.0f, 1.0f);
}

}  // namespace

double rootMeanSquareError(const FloatImage& a, const FloatImage& b, const std::vector<bool>* mask) {
  requireComparable(a, b);
  double sum = 0.0;
  size_t pixels = 0;
  for (size_t i = 0; i < pixelCount(a); ++i) {
    if (mask && !(*mask)[i]) continue;
    ++pixels;
    for (int c = 0; c < colorChannels(a); ++c) {
      const size_t k = i * size_t(a.channels) + size_t(c);
      const double d = double(a.pixels[k]) - double(b.pixels[k]);
      sum += d * d;
    }
  }
  const size_t count = pixels * size_t(colorChannels(a));
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

double peakSignalToNoise(double rmse) {
  if (rmse == 0.0) return std::numeric_limits<double>::infinity();
  return -20.0 * std::log10(rmse);
}

double structuralSimilarity(const FloatImage& aSrgb, const FloatImage& bSrgb) {
  requireComparable(aSrgb, bSrgb);
  if (aSrgb.width < kSsimWindow || aSrgb.height < kSsimWindow) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (int c = 0; c < colorChannels(aSrgb); ++c) sum += channelSsimSum(aSrgb, bSrgb, c);
  const double windows = double(aSrgb.width - kSsimWindow + 1) * double(aSrgb.height - kSsimWindow + 1);
  return sum / (windows * colorChannels(aSrgb));
}

double maxChannelDifference(const FloatImage& a, const FloatImage& b) {
  requireComparable(a, b);
  double d = 0.0;
  for (size_t i = 0; i < pixelCount(a); ++i) d = std::max(d, pixelDifference(a, b, i));
  return d;
}

double shareOverThreshold(const FloatImage& a, const FloatImage& b, double threshold) {
  requireComparable(a, b);
  size_t over = 0;
  for (size_t i = 0; i < pixelCount(a); ++i)
    if (pixelDifference(a, b, i) > threshold) ++over;
  return pixelCount(a) ? double(over) / double(pixelCount(a)) : 0.0;
}

size_t nonFiniteCount(const FloatImage& image) {
  size_t count = 0;
  for (size_t i = 0; i < pixelCount(image); ++i)
    for (int c = 0; c < colorChannels(image); ++c)
      count += !std::isfinite(image.pixels[i * size_t(image.channels) + size_t(c)]);
  return count;
}

FloatImage rgbaFloatImage(const float* rgba, int width, int height) {
  FloatImage image;
  image.width = width;
  image.height = height;
  image.channels = 4;
  image.pixels.assign(rgba, rgba + size_t(width) * size_t(height) * 4);
  return image;
}

FloatImage rgbFloatImage(const float* rgba, int width, int height) {
  FloatImage image{width, height, 3, std::vector<float>(size_t(width) * size_t(height) * 3)};
  for (size_t i = 0; i < size_t(width) * size_t(height); ++i)
    for (size_t c = 0; c < 3; ++c) image.pixels[i * 3 + c] = rgba[i * 4 + c];
  return image;
}

FloatImage linearToSrgbImage(const FloatImage& linear) {
  FloatImage out = linear;
  for (size_t i = 0; i < pixelCount(linear); ++i)
    for (int c = 0; c < colorChannels(linear); ++c) {
      float& v = out.pixels[i * size_t(out.channels) + size_t(c)];
      v = std::isfinite(v) ? float(linearToSrgb(std::clamp(double(v), 0.0, 1.0))) : 0.0f;
    }
  return out;
}

void clampForComparison(LinearImage& a, LinearImage& b) {
  if (!a.lowDynamicRange && !b.lowDynamicRange) return;
  clampToUnit(a.image);
  clampToUnit(b.image);
}

ImageMetrics measureImages(const FloatImage& reference, const FloatImage& test, double threshold) {
  ImageMetrics m;
  m.rmse = rootMeanSquareError(reference, test);
  m.psnr = peakSignalToNoise(m.rmse);
  m.ssim = structuralSimilarity(linearToSrgbImage(reference), linearToSrgbImage(test));
  m.maxDifference = maxChannelDifference(reference, test);
  m.shareOver = shareOverThreshold(reference, test, threshold);
  return m;
}
