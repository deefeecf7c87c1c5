#include "image_metrics.h"

#include "error.h"
#include "image_io.h"

#include <algorithm>
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

// The means over every kSsimWindow x kSsimWindow window wholly inside the w x h plane, row by
// row: (w - window + 1) x (h - window + 1) values, a sum along x and then along y.
std::vector<double> windowMeans(const std::vector<double>& plane, int w, int h) {
  const int ow = w - kSsimWindow + 1, oh = h - kSsimWindow + 1;
  std::vector<double> rows(size_t(ow) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < kSsimWindow; ++k) s += plane[size_t(y) * size_t(w) + size_t(x + k)];
      rows[size_t(y) * size_t(ow) + size_t(x)] = s;
    }
  std::vector<double> out(size_t(ow) * size_t(oh));
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < kSsimWindow; ++k) s += rows[size_t(y + k) * size_t(ow) + size_t(x)];
      out[size_t(y) * size_t(ow) + size_t(x)] = s / (kSsimWindow * kSsimWindow);
    }
  return out;
}

// The sum of the structural similarity over the windows of channel c.
double channelSsimSum(const FloatImage& a, const FloatImage& b, int c) {
  const size_t n = pixelCount(a);
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (size_t i = 0; i < n; ++i) {
    x[i] = a.pixels[i * size_t(a.channels) + size_t(c)];
    y[i] = b.pixels[i * size_t(b.channels) + size_t(c)];
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const int w = a.width, h = a.height;
  const std::vector<double> ux = windowMeans(x, w, h), uy = windowMeans(y, w, h);
  const std::vector<double> uxx = windowMeans(xx, w, h), uyy = windowMeans(yy, w, h), uxy = windowMeans(xy, w, h);
  const double np = kSsimWindow * kSsimWindow, covNorm = np / (np - 1.0);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double sum = 0.0;
  for (size_t i = 0; i < ux.size(); ++i) {
    const double vx = covNorm * (uxx[i] - ux[i] * ux[i]), vy = covNorm * (uyy[i] - uy[i] * uy[i]);
    const double vxy = covNorm * (uxy[i] - ux[i] * uy[i]);
    sum += (2.0 * ux[i] * uy[i] + c1) * (2.0 * vxy + c2) / ((ux[i] * ux[i] + uy[i] * uy[i] + c1) * (vx + vy + c2));
  }
  return sum;
}

void clampToUnit(FloatImage& image) {
  for (float& v : image.pixels) v = std::clamp(v, 0.0f, 1.0f);
}

}  // namespace

double rootMeanSquareError(const FloatImage& a, const FloatImage& b) {
  requireComparable(a, b);
  double sum = 0.0;
  for (size_t i = 0; i < pixelCount(a); ++i)
    for (int c = 0; c < colorChannels(a); ++c) {
      const size_t k = i * size_t(a.channels) + size_t(c);
      const double d = double(a.pixels[k]) - double(b.pixels[k]);
      sum += d * d;
    }
  const size_t count = pixelCount(a) * size_t(colorChannels(a));
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
