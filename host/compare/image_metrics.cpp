#include "image_metrics.h"

#include "error.h"
#include "float_memo.h"
#include "image_file.h"
#include "srgb.h"
#include "parallel.h"

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

// What linearToSrgbImage makes of a linear value.
float srgbEncoded(float v) { return std::isfinite(v) ? float(linearToSrgb(std::clamp(double(v), 0.0, 1.0))) : 0.0f; }
using SrgbEncoder = FloatMemo<float, srgbEncoded>;

// Channel c of row y, sRGB-encoded (as linearToSrgbImage encodes it) or as stored.
void readChannelRow(const FloatImage& image, int y, int c, SrgbEncoder* encode, std::vector<double>* out) {
  for (int x = 0; x < image.width; ++x) {
    const float v = image.at(x, y, c);
    (*out)[size_t(x)] = encode ? (*encode)(v) : v;
  }
}

// The five sums of SSIM (x, y, x^2, y^2, xy) over every run of kSsimWindow pixels along one row
// (`ow` runs): sums[q][x] for the run from x.
void rowWindowSums(const std::vector<double>& a, const std::vector<double>& b, size_t ow, double* const sums[5]) {
  for (size_t x = 0; x < ow; ++x) {
    double s[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    for (size_t k = 0; k < size_t(kSsimWindow); ++k) {
      const double u = a[x + k], v = b[x + k];
      s[0] += u;
      s[1] += v;
      s[2] += u * u;
      s[3] += v * v;
      s[4] += u * v;
    }
    for (size_t q = 0; q < 5; ++q) sums[q][x] = s[q];
  }
}

// The structural similarity of one window from its means of x, y, x^2, y^2 and xy, with
// sample (N - 1) variances and covariance.
double windowSsim(double ux, double uy, double uxx, double uyy, double uxy) {
  const double np = kSsimWindow * kSsimWindow, covNorm = np / (np - 1.0);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  const double vx = covNorm * (uxx - ux * ux), vy = covNorm * (uyy - uy * uy), vxy = covNorm * (uxy - ux * uy);
  return (2.0 * ux * uy + c1) * (2.0 * vxy + c2) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
}

// The row sums of the last kSsimWindow rows of a channel, row y in slot y % kSsimWindow.
struct SsimRowRing {
  size_t ow;
  std::array<std::vector<double>, 5> sums;  // kSsimWindow rows of ow each
  explicit SsimRowRing(size_t windows) : ow(windows) {
    for (std::vector<double>& s : sums) s.assign(size_t(kSsimWindow) * ow, 0.0);
  }
  double* at(size_t q, int y) { return &sums[q][size_t(y % kSsimWindow) * ow]; }
};

// Adds to `sum`, one after another, the structural similarity of the windows whose top row is
// `top`: the row sums of rows top .. top + kSsimWindow - 1 added along y.
void addWindowRowSsim(SsimRowRing& ring, int top, std::array<std::vector<double>, 5>& means, double* sum) {
  const double np = kSsimWindow * kSsimWindow;
  for (size_t q = 0; q < 5; ++q) {
    means[q].assign(ring.ow, 0.0);
    for (int k = 0; k < kSsimWindow; ++k) {
      const double* row = ring.at(q, top + k);
      for (size_t x = 0; x < ring.ow; ++x) means[q][x] += row[x];
    }
    for (double& m : means[q]) m /= np;
  }
  for (size_t x = 0; x < ring.ow; ++x) *sum += windowSsim(means[0][x], means[1][x], means[2][x], means[3][x], means[4][x]);
}

// The sum of the structural similarity over the windows of channel c, a row at a time: each
// row's window sums are kept for kSsimWindow rows, then added along y.
double channelSsimSum(const FloatImage& a, const FloatImage& b, int c, bool encode) {
  const size_t ow = size_t(a.width - kSsimWindow + 1);
  SsimRowRing ring(ow);
  std::array<std::vector<double>, 5> means;
  std::vector<double> u(size_t(a.width)), v(size_t(a.width));
  SrgbEncoder encoder;
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y) {
    readChannelRow(a, y, c, encode ? &encoder : nullptr, &u);
    readChannelRow(b, y, c, encode ? &encoder : nullptr, &v);
    double* const sums[5] = {ring.at(0, y), ring.at(1, y), ring.at(2, y), ring.at(3, y), ring.at(4, y)};
    rowWindowSums(u, v, ow, sums);
    if (y >= kSsimWindow - 1) addWindowRowSsim(ring, y - (kSsimWindow - 1), means, &sum);
  }
  return sum;
}

// structuralSimilarity of a and b as stored, or of their sRGB encodings; the channels on
// threads of their own.
double ssimOf(const FloatImage& a, const FloatImage& b, bool encode) {
  requireComparable(a, b);
  if (a.width < kSsimWindow || a.height < kSsimWindow) return std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> channelSums{};
  forEachRowInParallel(colorChannels(a), 0, [&](int c) { channelSums[size_t(c)] = channelSsimSum(a, b, c, encode); });
  double sum = 0.0;
  for (int c = 0; c < colorChannels(a); ++c) sum += channelSums[size_t(c)];
  const double windows = double(a.width - kSsimWindow + 1) * double(a.height - kSsimWindow + 1);
  return sum / (windows * colorChannels(a));
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

double structuralSimilarity(const FloatImage& aSrgb, const FloatImage& bSrgb) { return ssimOf(aSrgb, bSrgb, false); }

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

FloatImage linearToSrgbImage(const FloatImage& linear) {
  FloatImage out = linear;
  for (size_t i = 0; i < pixelCount(linear); ++i)
    for (int c = 0; c < colorChannels(linear); ++c) {
      float& v = out.pixels[i * size_t(out.channels) + size_t(c)];
      v = srgbEncoded(v);
    }
  return out;
}

void linearToSrgbRow(const FloatImage& linear, int y, int x0, int x1, float* rgb) {
  thread_local SrgbEncoder srgbEncoded;
  for (int x = x0; x < x1; ++x)
    for (int c = 0; c < 3; ++c) rgb[size_t(x - x0) * 3 + size_t(c)] = srgbEncoded(linear.at(x, y, c));
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
  m.ssim = ssimOf(reference, test, true);
  m.maxDifference = maxChannelDifference(reference, test);
  m.shareOver = shareOverThreshold(reference, test, threshold);
  return m;
}
