#include "flip.h"

#include "error.h"

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Linear sRGB (D65) to CIE XYZ, the matrix of IEC 61966-2-1 given row by row.
const glm::dmat3& rgbToXyzMatrix() {
  static const glm::dmat3 m = glm::transpose(glm::dmat3(0.4124564, 0.3575761, 0.1804375,  //
                                                        0.2126729, 0.7151522, 0.0721750,  //
                                                        0.0193339, 0.1191920, 0.9503041));
  return m;
}

// XYZ of sRGB white (1, 1, 1): the reference white of YCxCz and L*a*b*.
const glm::dvec3& whiteXyz() {
  static const glm::dvec3 white = rgbToXyzMatrix() * glm::dvec3(1.0);
  return white;
}

// The cube root of CIE L*a*b*, linear below (6/29)^3.
double labCurve(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// One channel of `image`, as doubles.
std::vector<double> channelOf(const FloatImage& image, int c) {
  std::vector<double> out(size_t(image.width) * size_t(image.height));
  for (size_t i = 0; i < out.size(); ++i) out[i] = image.pixels[i * size_t(image.channels) + size_t(c)];
  return out;
}

FloatImage blankLike(const FloatImage& image, int channels) {
  FloatImage out;
  out.width = image.width;
  out.height = image.height;
  out.channels = channels;
  out.pixels.assign(size_t(image.width) * size_t(image.height) * size_t(channels), 0.0f);
  return out;
}

// `plane` (w x h) filtered along x with `k` into `out`, each row padded with its edge pixels.
void filterRows(const std::vector<double>& plane, int w, int h, const Kernel1D& k, std::vector<double>* out) {
  std::vector<double> padded(size_t(w + 2 * k.radius));
  for (int y = 0; y < h; ++y) {
    const double* row = &plane[size_t(y) * size_t(w)];
    for (int i = 0; i < int(padded.size()); ++i) padded[size_t(i)] = row[std::clamp(i - k.radius, 0, w - 1)];
    double* dst = &(*out)[size_t(y) * size_t(w)];
    for (int x = 0; x < w; ++x) {
      double sum = 0.0;
      for (size_t t = 0; t < k.weights.size(); ++t) sum += k.weights[t] * padded[size_t(x) + t];
      dst[x] = sum;
    }
  }
}

// `plane` (w x h) filtered along y with `k` and added to `out`, whole rows at a time, the edge
// rows repeated.
void addFilteredColumns(const std::vector<double>& plane, int w, int h, const Kernel1D& k, std::vector<double>* out) {
  for (int y = 0; y < h; ++y) {
    double* dst = &(*out)[size_t(y) * size_t(w)];
    for (int d = -k.radius; d <= k.radius; ++d) {
      const double weight = k.weights[size_t(d + k.radius)];
      const double* src = &plane[size_t(std::clamp(y + d, 0, h - 1)) * size_t(w)];
      for (int x = 0; x < w; ++x) dst[x] += weight * src[x];
    }
  }
}

std::vector<double> filterPlane(const std::vector<double>& plane, int w, int h, const SeparableKernel& kernel) {
  std::vector<double> out(plane.size(), 0.0), rows(plane.size());
  for (const KernelTerm& term : kernel) {
    filterRows(plane, w, h, term.x, &rows);
    addFilteredColumns(rows, w, h, term.y, &out);
  }
  return out;
}

// A Gaussian's 1D samples exp(-pi^2 (i / ppd)^2 / b) at offsets -r..r.
Kernel1D csfGaussian(double b, int radius, double pixelsPerDegree) {
  Kernel1D k{radius, std::vector<double>(size_t(2 * radius + 1))};
  for (int i = -radius; i <= radius; ++i) {
    const double x = i / pixelsPerDegree;
    k.weights[size_t(i + radius)] = std::exp(-kPi * kPi * x * x / b);
  }
  return k;
}

double sumOf(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

// The paper's (a1, b1, a2, b2) of each channel's contrast sensitivity function.
struct CsfConstants {
  double a1, b1, a2, b2;
};
CsfConstants csfConstants(CsfChannel channel) {
  switch (channel) {
    case CsfChannel::Achromatic: return {1.0, 0.0047, 0.0, 1e-5};
    case CsfChannel::RedGreen: return {1.0, 0.0053, 0.0, 1e-5};
    case CsfChannel::BlueYellow: return {34.1, 0.04, 13.5, 0.025};
  }
  return {1.0, 0.0047, 0.0, 1e-5};
}

void requireSameSize(const FloatImage& a, const FloatImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error(ErrorKind::Internal, "FLIP compares images of one size, got " + std::to_string(a.width) + "x" +
                                         std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                                         std::to_string(b.height));
}

}  // namespace

glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb) { return rgbToXyzMatrix() * rgb; }

glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz) {
  static const glm::dmat3 inverse = glm::inverse(rgbToXyzMatrix());
  return inverse * xyz;
}

glm::dvec3 xyzToYcxcz(const glm::dvec3& xyz) {
  const glm::dvec3 r = xyz / whiteXyz();
  return {116.0 * r.y - 16.0, 500.0 * (r.x - r.y), 200.0 * (r.y - r.z)};
}

glm::dvec3 ycxczToXyz(const glm::dvec3& ycxcz) {
  const double y = (ycxcz.x + 16.0) / 116.0;
  return glm::dvec3(ycxcz.y / 500.0 + y, y, y - ycxcz.z / 200.0) * whiteXyz();
}

glm::dvec3 xyzToLab(const glm::dvec3& xyz) {
  const glm::dvec3 r = xyz / whiteXyz();
  const double fx = labCurve(r.x), fy = labCurve(r.y), fz = labCurve(r.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::dvec3 huntAdjust(const glm::dvec3& lab) { return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z}; }

double hyab(const glm::dvec3& lab1, const glm::dvec3& lab2) {
  const double da = lab1.y - lab2.y, db = lab1.z - lab2.z;
  return std::abs(lab1.x - lab2.x) + std::sqrt(da * da + db * db);
}

double flipMaxColorDistance() {
  static const double cmax = [] {
    const glm::dvec3 green = huntAdjust(xyzToLab(linearRgbToXyz({0.0, 1.0, 0.0})));
    const glm::dvec3 blue = huntAdjust(xyzToLab(linearRgbToXyz({0.0, 0.0, 1.0})));
    return std::pow(hyab(green, blue), kFlipColorExponent);
  }();
  return cmax;
}

double redistributeColorError(double hyabDistance) {
  const double cmax = flipMaxColorDistance();
  const double breakPoint = kFlipColorBreak * cmax;
  const double e = std::pow(hyabDistance, kFlipColorExponent);
  if (e < breakPoint) return kFlipColorBreakError / breakPoint * e;
  return std::min(1.0, kFlipColorBreakError + (e - breakPoint) / (cmax - breakPoint) * (1.0 - kFlipColorBreakError));
}

double combineFlipErrors(double colorError, double featureError) { return std::pow(colorError, 1.0 - featureError); }

int csfRadius(double pixelsPerDegree) {
  const double widestB = 0.04;  // blue-yellow's b1
  return int(std::ceil(3.0 * std::sqrt(widestB / (2.0 * kPi * kPi)) * pixelsPerDegree));
}

SeparableKernel csfKernel(CsfChannel channel, double pixelsPerDegree) {
  const CsfConstants k = csfConstants(channel);
  const int radius = csfRadius(pixelsPerDegree);
  SeparableKernel kernel;
  double total = 0.0;
  for (auto [a, b] : {std::pair{k.a1, k.b1}, std::pair{k.a2, k.b2}}) {
    if (a == 0.0) continue;
    KernelTerm term{csfGaussian(b, radius, pixelsPerDegree), csfGaussian(b, radius, pixelsPerDegree)};
    for (double& w : term.x.weights) w *= a * std::sqrt(kPi / b);
    total += sumOf(term.x.weights) * sumOf(term.y.weights);
    kernel.push_back(term);
  }
  for (KernelTerm& term : kernel)
    for (double& w : term.x.weights) w /= total;
  return kernel;
}

int featureRadius(double pixelsPerDegree) {
  return int(std::ceil(3.0 * 0.5 * kFlipFeatureWidthDegrees * pixelsPerDegree));
}

KernelTerm featureKernel(FeatureKind kind, double pixelsPerDegree) {
  const double sigma = 0.5 * kFlipFeatureWidthDegrees * pixelsPerDegree;
  const int radius = featureRadius(pixelsPerDegree);
  KernelTerm term{{radius, {}}, {radius, {}}};
  for (int i = -radius; i <= radius; ++i) {
    const double g = std::exp(-double(i) * i / (2.0 * sigma * sigma));
    term.y.weights.push_back(g);
    term.x.weights.push_back(kind == FeatureKind::Edge ? -i * g : (double(i) * i / (sigma * sigma) - 1.0) * g);
  }
  // With y's weights all positive, the 2D kernel's positive and negative parts are x's parts
  // times y's sum: normalising x's parts and y's sum separately normalises the 2D kernel's.
  double positive = 0.0, negative = 0.0;
  for (double w : term.x.weights) (w > 0.0 ? positive : negative) += w;
  for (double& w : term.x.weights) w /= w > 0.0 ? positive : -negative;
  const double ySum = sumOf(term.y.weights);
  for (double& w : term.y.weights) w /= ySum;
  return term;
}

std::vector<double> denseKernel(const SeparableKernel& kernel) {
  const int r = kernel.empty() ? 0 : kernel.front().x.radius;
  const size_t n = size_t(2 * r + 1);
  std::vector<double> out(n * n, 0.0);
  for (const KernelTerm& t : kernel)
    for (size_t y = 0; y < n; ++y)
      for (size_t x = 0; x < n; ++x) out[y * n + x] += t.x.weights[x] * t.y.weights[y];
  return out;
}

FloatImage filterImage(const FloatImage& image, const SeparableKernel& kernel) {
  FloatImage out = blankLike(image, image.channels);
  for (int c = 0; c < image.channels; ++c) {
    std::vector<double> plane = filterPlane(channelOf(image, c), image.width, image.height, kernel);
    for (size_t i = 0; i < plane.size(); ++i) out.pixels[i * size_t(image.channels) + size_t(c)] = float(plane[i]);
  }
  return out;
}

FloatImage srgbToYcxcz(const FloatImage& srgb) {
  FloatImage out = blankLike(srgb, 3);
  for (size_t i = 0; i < size_t(srgb.width) * size_t(srgb.height); ++i) {
    const float* p = &srgb.pixels[i * size_t(srgb.channels)];
    const glm::dvec3 rgb(srgbToLinear(p[0]), srgbToLinear(p[1]), srgbToLinear(p[2]));
    const glm::dvec3 ycc = xyzToYcxcz(linearRgbToXyz(rgb));
    for (int c = 0; c < 3; ++c) out.pixels[i * 3 + size_t(c)] = float(ycc[c]);
  }
  return out;
}

FloatImage filterCsf(const FloatImage& ycxcz, double pixelsPerDegree) {
  FloatImage out = blankLike(ycxcz, 3);
  const CsfChannel channels[3] = {CsfChannel::Achromatic, CsfChannel::RedGreen, CsfChannel::BlueYellow};
  for (int c = 0; c < 3; ++c) {
    const SeparableKernel kernel = csfKernel(channels[c], pixelsPerDegree);
    std::vector<double> plane = filterPlane(channelOf(ycxcz, c), ycxcz.width, ycxcz.height, kernel);
    for (size_t i = 0; i < plane.size(); ++i) out.pixels[i * 3 + size_t(c)] = float(plane[i]);
  }
  return out;
}

FloatImage ycxczToHuntLab(const FloatImage& ycxcz) {
  FloatImage out = blankLike(ycxcz, 3);
  for (size_t i = 0; i < size_t(ycxcz.width) * size_t(ycxcz.height); ++i) {
    const float* p = &ycxcz.pixels[i * 3];
    const glm::dvec3 rgb = glm::clamp(xyzToLinearRgb(ycxczToXyz({p[0], p[1], p[2]})), 0.0, 1.0);
    const glm::dvec3 lab = huntAdjust(xyzToLab(linearRgbToXyz(rgb)));
    for (int c = 0; c < 3; ++c) out.pixels[i * 3 + size_t(c)] = float(lab[c]);
  }
  return out;
}

FloatImage colorErrorMap(const FloatImage& referenceLab, const FloatImage& testLab) {
  requireSameSize(referenceLab, testLab);
  FloatImage out = blankLike(referenceLab, 1);
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    const float* r = &referenceLab.pixels[i * 3];
    const float* t = &testLab.pixels[i * 3];
    out.pixels[i] = float(redistributeColorError(hyab({r[0], r[1], r[2]}, {t[0], t[1], t[2]})));
  }
  return out;
}

FeatureMaps detectFeatures(const FloatImage& ycxcz, double pixelsPerDegree) {
  std::vector<double> y = channelOf(ycxcz, 0);
  for (double& v : y) v = (v + 16.0) / 116.0;
  FeatureMaps maps{blankLike(ycxcz, 1), blankLike(ycxcz, 1)};
  for (FeatureKind kind : {FeatureKind::Edge, FeatureKind::Point}) {
    const KernelTerm alongX = featureKernel(kind, pixelsPerDegree);
    const KernelTerm alongY{alongX.y, alongX.x};
    const std::vector<double> dx = filterPlane(y, ycxcz.width, ycxcz.height, {alongX});
    const std::vector<double> dy = filterPlane(y, ycxcz.width, ycxcz.height, {alongY});
    FloatImage& map = kind == FeatureKind::Edge ? maps.edges : maps.points;
    for (size_t i = 0; i < y.size(); ++i) map.pixels[i] = float(std::hypot(dx[i], dy[i]));
  }
  return maps;
}

FloatImage featureErrorMap(const FeatureMaps& reference, const FeatureMaps& test) {
  requireSameSize(reference.edges, test.edges);
  FloatImage out = blankLike(reference.edges, 1);
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    const double edge = std::abs(double(reference.edges.pixels[i]) - test.edges.pixels[i]);
    const double point = std::abs(double(reference.points.pixels[i]) - test.points.pixels[i]);
    out.pixels[i] = float(std::pow(std::max(edge, point) / std::sqrt(2.0), kFlipFeatureExponent));
  }
  return out;
}

FloatImage flipErrorMap(const FloatImage& referenceSrgb, const FloatImage& testSrgb) {
  requireSameSize(referenceSrgb, testSrgb);
  const FloatImage referenceYcxcz = srgbToYcxcz(referenceSrgb);
  const FloatImage testYcxcz = srgbToYcxcz(testSrgb);
  const FloatImage color =
      colorErrorMap(ycxczToHuntLab(filterCsf(referenceYcxcz, kFlipPixelsPerDegree)),
                    ycxczToHuntLab(filterCsf(testYcxcz, kFlipPixelsPerDegree)));
  const FloatImage feature = featureErrorMap(detectFeatures(referenceYcxcz, kFlipPixelsPerDegree),
                                             detectFeatures(testYcxcz, kFlipPixelsPerDegree));
  FloatImage error = blankLike(referenceSrgb, 1);
  for (size_t i = 0; i < error.pixels.size(); ++i)
    error.pixels[i] = float(combineFlipErrors(color.pixels[i], feature.pixels[i]));
  return error;
}

double flipMean(const FloatImage& error) {
  if (error.pixels.empty()) return 0.0;
  double sum = 0.0;
  for (float e : error.pixels) sum += e;
  return sum / double(error.pixels.size());
}

std::array<uint8_t, 3> heatmapColor(double error) {
  // Anchors at 0, 0.2, ..., 1 (sRGB codes), interpolated linearly between neighbours.
  static const double anchors[6][3] = {{5, 4, 22},     {62, 16, 110},  {138, 42, 128},
                                       {216, 74, 108}, {250, 158, 110}, {252, 248, 190}};
  const double t = std::clamp(std::isfinite(error) ? error : 1.0, 0.0, 1.0) * 5.0;
  const int i = std::min(4, int(t));
  const double f = t - i;
  std::array<uint8_t, 3> rgb{};
  for (int c = 0; c < 3; ++c) rgb[size_t(c)] = uint8_t(std::lround(anchors[i][c] + f * (anchors[i + 1][c] - anchors[i][c])));
  return rgb;
}

ImageRGBA8 flipHeatmap(const FloatImage& error) {
  ImageRGBA8 out;
  out.width = error.width;
  out.height = error.height;
  out.pixels.resize(size_t(error.width) * size_t(error.height) * 4);
  for (size_t i = 0; i < size_t(error.width) * size_t(error.height); ++i) {
    const std::array<uint8_t, 3> rgb = heatmapColor(error.pixels[i * size_t(error.channels)]);
    out.pixels[i * 4 + 0] = rgb[0];
    out.pixels[i * 4 + 1] = rgb[1];
    out.pixels[i * 4 + 2] = rgb[2];
    out.pixels[i * 4 + 3] = 255;
  }
  return out;
}
