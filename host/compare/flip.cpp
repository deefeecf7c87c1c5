#include "flip.h"

#include "srgb.h"

#include "error.h"
#include "float_memo.h"
#include "parallel.h"

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

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

// Columns [x0, x1) of an image w wide, and the source columns [sx0, sx1) that filters of
// radius up to `margin` read for them (the edge columns repeated outside the image).
struct ColumnSpan {
  int w, x0, x1, sx0, sx1;
  ColumnSpan(int width, int first, int end, int margin)
      : w(width), x0(first), x1(end), sx0(std::max(0, first - margin)), sx1(std::min(width, end + margin)) {}
  size_t outputs() const { return size_t(x1 - x0); }
  size_t sources() const { return size_t(sx1 - sx0); }
};

// The span's source columns of a row (`row`, from sx0) filtered along x with `k` into `dst`
// (its columns, from x0), padded with the image's edge pixels in `padded` (outputs + 2 radius
// values). Each pixel's sum runs over the weights in order; four pixels are summed side by side.
void filterRow(const double* row, const ColumnSpan& span, const Kernel1D& k, double* padded, double* dst) {
  const int n = span.x1 - span.x0;
  for (int i = 0; i < n + 2 * k.radius; ++i) padded[i] = row[std::clamp(span.x0 + i - k.radius, 0, span.w - 1) - span.sx0];
  constexpr int kLanes = 4;
  const size_t taps = k.weights.size();
  int x = 0;
  for (; x + kLanes <= n; x += kLanes) {
    double sum[kLanes] = {0.0, 0.0, 0.0, 0.0};
    for (size_t t = 0; t < taps; ++t)
      for (int j = 0; j < kLanes; ++j) sum[j] += k.weights[t] * padded[size_t(x + j) + t];
    for (int j = 0; j < kLanes; ++j) dst[x + j] = sum[j];
  }
  for (; x < n; ++x) {
    double sum = 0.0;
    for (size_t t = 0; t < taps; ++t) sum += k.weights[t] * padded[size_t(x) + t];
    dst[x] = sum;
  }
}

// The columns of a span of a plane h rows high filtered with a separable kernel a row at a
// time. Rows (the span's source columns) go in from the top (push); each kernel term keeps the
// last `slots` of them filtered along x, row y in slot y % slots. Output row y sums the filtered
// rows y - r .. y + r (clamped to the plane, the edge rows repeated) along y, term after term,
// so it may be read once the rows up to y + r, or the last, are in and none past y - r + slots.
class StreamedFilter {
 public:
  StreamedFilter(const SeparableKernel& kernel, const ColumnSpan& span, int h, int slots)
      : kernel_(kernel), span_(span), h_(h), slots_(slots), padded_(span.outputs() + size_t(2 * radius())) {
    for (size_t t = 0; t < kernel.size(); ++t) rings_.emplace_back(size_t(slots) * span.outputs());
  }
  int radius() const { return kernel_.empty() ? 0 : kernel_.front().x.radius; }
  void push(int y, const double* row) {
    for (size_t t = 0; t < kernel_.size(); ++t) filterRow(row, span_, kernel_[t].x, padded_.data(), slot(t, y));
  }
  void output(int y, double* out) const {
    const size_t n = span_.outputs();
    std::fill(out, out + n, 0.0);
    for (size_t t = 0; t < kernel_.size(); ++t) {
      const Kernel1D& k = kernel_[t].y;
      for (int d = -k.radius; d <= k.radius; ++d) {
        const double weight = k.weights[size_t(d + k.radius)];
        const double* src = slot(t, std::clamp(y + d, 0, h_ - 1));
        for (size_t x = 0; x < n; ++x) out[x] += weight * src[x];
      }
    }
  }

 private:
  double* slot(size_t t, int y) { return &rings_[t][size_t(y % slots_) * span_.outputs()]; }
  const double* slot(size_t t, int y) const { return &rings_[t][size_t(y % slots_) * span_.outputs()]; }

  SeparableKernel kernel_;
  ColumnSpan span_;
  int h_, slots_;
  std::vector<std::vector<double>> rings_;
  std::vector<double> padded_;
};

// Slots a StreamedFilter of radius r needs when rows are pushed `ahead` rows past the one read.
int filterSlots(int r, int ahead, int h) { return std::min(r + ahead + 1, h); }


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


const CsfChannel kCsfChannels[3] = {CsfChannel::Achromatic, CsfChannel::RedGreen, CsfChannel::BlueYellow};

// The y-direction detector of an x-direction one.
KernelTerm transposed(const KernelTerm& term) { return {term.y, term.x}; }

double srgbDecoded(float v) { return srgbToLinear(v); }
using SrgbDecoder = FloatMemo<double, srgbDecoded>;

// --- one pixel of each stage, values as the stages' float images hold them ---
void ycxczPixel(const float* srgb, float* ycxcz, SrgbDecoder& decode) {
  const glm::dvec3 rgb(decode(srgb[0]), decode(srgb[1]), decode(srgb[2]));
  const glm::dvec3 ycc = xyzToYcxcz(linearRgbToXyz(rgb));
  for (int c = 0; c < 3; ++c) ycxcz[c] = float(ycc[c]);
}

void huntLabPixel(const float* ycxcz, float* lab) {
  const glm::dvec3 rgb = glm::clamp(xyzToLinearRgb(ycxczToXyz({ycxcz[0], ycxcz[1], ycxcz[2]})), 0.0, 1.0);
  const glm::dvec3 hunt = huntAdjust(xyzToLab(linearRgbToXyz(rgb)));
  for (int c = 0; c < 3; ++c) lab[c] = float(hunt[c]);
}

float colorErrorPixel(const float* referenceLab, const float* testLab) {
  const float *r = referenceLab, *t = testLab;
  return float(redistributeColorError(hyab({r[0], r[1], r[2]}, {t[0], t[1], t[2]})));
}

// The achromatic channel the features are detected in: (Y + 16) / 116 of YCxCz.
double featureLuminance(double y) { return (y + 16.0) / 116.0; }

float featureErrorPixel(float referenceEdge, float referencePoint, float testEdge, float testPoint) {
  const double edge = std::abs(double(referenceEdge) - testEdge);
  const double point = std::abs(double(referencePoint) - testPoint);
  return float(std::pow(std::max(edge, point) / std::sqrt(2.0), kFlipFeatureExponent));
}

// The first 3 channels of each row of `image`.
SrgbRows imageRows(const FloatImage& image) {
  return [&image](int y, int x0, int x1, float* rgb) {
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) rgb[size_t(x - x0) * 3 + size_t(c)] = image.at(x, y, c);
  };
}

// The radius of the widest FLIP filter: how far past a pixel its stages read.
int flipReach() { return std::max(csfRadius(kFlipPixelsPerDegree), featureRadius(kFlipPixelsPerDegree)); }

// One image's FLIP stages over a span of columns, a row at a time, from its sRGB rows: the
// colour filtered by the contrast sensitivity functions as Hunt-adjusted L*a*b*, and the edge
// and point strengths. Rows are read in order from `first`; each source row is converted and
// filtered once, as the rows up to flipReach past the one read are needed.
class FlipImageRows {
 public:
  FlipImageRows(const ColumnSpan& span, int h, const SrgbRows& source, int first)
      : span_(span), h_(h), ahead_(flipReach()), next_(std::max(0, first - ahead_)), source_(source),
        srgb_(span.sources() * 3), ycxcz_(span.sources() * 3), filtered_(span.outputs() * 3),
        plane_(span.sources()), dy_(span.outputs()) {
    for (CsfChannel channel : kCsfChannels) addFilter(csfKernel(channel, kFlipPixelsPerDegree), &csf_);
    for (FeatureKind kind : {FeatureKind::Edge, FeatureKind::Point}) {
      const KernelTerm alongX = featureKernel(kind, kFlipPixelsPerDegree);
      addFilter({alongX}, &features_);
      addFilter({transposed(alongX)}, &features_);
    }
  }

  // Row y's Hunt-adjusted L*a*b* (3 floats a pixel), edges and points (1 float a pixel), over
  // the span's columns.
  void read(int y, float* lab, float* edges, float* points) {
    for (; next_ <= std::min(h_ - 1, y + ahead_); ++next_) pushSource(next_);
    const size_t n = span_.outputs();
    for (size_t c = 0; c < 3; ++c) {
      csf_[c].output(y, plane_.data());
      for (size_t x = 0; x < n; ++x) filtered_[x * 3 + c] = float(plane_[x]);
    }
    for (size_t x = 0; x < n; ++x) huntLabPixel(&filtered_[x * 3], &lab[x * 3]);
    for (size_t kind = 0; kind < 2; ++kind) {
      features_[2 * kind].output(y, plane_.data());
      features_[2 * kind + 1].output(y, dy_.data());
      float* map = kind == 0 ? edges : points;
      for (size_t x = 0; x < n; ++x) map[x] = float(std::hypot(plane_[x], dy_[x]));
    }
  }

 private:
  void addFilter(const SeparableKernel& kernel, std::vector<StreamedFilter>* filters) {
    filters->emplace_back(kernel, span_, h_, filterSlots(kernel.front().x.radius, ahead_, h_));
  }

  // Source row y to YCxCz, its channels into the filters.
  void pushSource(int y) {
    const size_t n = span_.sources();
    source_(y, span_.sx0, span_.sx1, srgb_.data());
    for (size_t x = 0; x < n; ++x) ycxczPixel(&srgb_[x * 3], &ycxcz_[x * 3], decode_);
    for (size_t c = 0; c < 3; ++c) {
      for (size_t x = 0; x < n; ++x) plane_[x] = ycxcz_[x * 3 + c];
      csf_[c].push(y, plane_.data());
    }
    for (size_t x = 0; x < n; ++x) plane_[x] = featureLuminance(ycxcz_[x * 3]);
    for (StreamedFilter& filter : features_) filter.push(y, plane_.data());
  }

  ColumnSpan span_;
  int h_, ahead_, next_;
  const SrgbRows& source_;
  std::vector<StreamedFilter> csf_;       // Y, Cx, Cz
  std::vector<StreamedFilter> features_;  // edges along x and y, points along x and y
  std::vector<float> srgb_, ycxcz_, filtered_;
  std::vector<double> plane_, dy_;
  SrgbDecoder decode_;
};

// Rows [y0, y1) by columns [x0, x1) of the FLIP error map of two images given by their sRGB
// rows.
void flipTile(const SrgbRows& reference, const SrgbRows& test, int y0, int y1, int x0, int x1, FloatImage* error) {
  const ColumnSpan span(error->width, x0, x1, flipReach());
  FlipImageRows referenceRows(span, error->height, reference, y0), testRows(span, error->height, test, y0);
  const size_t n = span.outputs();
  std::vector<float> referenceLab(n * 3), testLab(n * 3), referenceEdges(n), referencePoints(n), testEdges(n), testPoints(n);
  for (int y = y0; y < y1; ++y) {
    referenceRows.read(y, referenceLab.data(), referenceEdges.data(), referencePoints.data());
    testRows.read(y, testLab.data(), testEdges.data(), testPoints.data());
    float* out = &error->pixels[size_t(y) * size_t(error->width) + size_t(x0)];
    for (size_t x = 0; x < n; ++x) {
      const float color = colorErrorPixel(&referenceLab[x * 3], &testLab[x * 3]);
      const float feature = featureErrorPixel(referenceEdges[x], referencePoints[x], testEdges[x], testPoints[x]);
      out[x] = float(combineFlipErrors(color, feature));
    }
  }
}

// Bands of the error map computed in parallel: one per processor thread, each at least
// kFlipBandRows rows (a band's filters start flipReach rows above it).
constexpr int kFlipBandRows = 512;
int flipBandCount(int height) {
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(height / kFlipBandRows, 1, threads);
}

}  // namespace

std::vector<double> filterPlane(const std::vector<double>& plane, int w, int h, const SeparableKernel& kernel) {
  const int r = kernel.empty() ? 0 : kernel.front().x.radius;
  StreamedFilter filter(kernel, ColumnSpan(w, 0, w, r), h, filterSlots(r, r, h));
  std::vector<double> out(plane.size());
  int pushed = 0;
  for (int y = 0; y < h; ++y) {
    for (; pushed <= std::min(h - 1, y + r); ++pushed) filter.push(pushed, &plane[size_t(pushed) * size_t(w)]);
    filter.output(y, &out[size_t(y) * size_t(w)]);
  }
  return out;
}

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

FloatImage srgbToYcxcz(const FloatImage& srgb) {
  FloatImage out = blankLike(srgb, 3);
  SrgbDecoder decode;
  for (size_t i = 0; i < size_t(srgb.width) * size_t(srgb.height); ++i)
    ycxczPixel(&srgb.pixels[i * size_t(srgb.channels)], &out.pixels[i * 3], decode);
  return out;
}

FloatImage filterCsf(const FloatImage& ycxcz, double pixelsPerDegree) {
  FloatImage out = blankLike(ycxcz, 3);
  for (int c = 0; c < 3; ++c) {
    const SeparableKernel kernel = csfKernel(kCsfChannels[c], pixelsPerDegree);
    std::vector<double> plane = filterPlane(channelOf(ycxcz, c), ycxcz.width, ycxcz.height, kernel);
    for (size_t i = 0; i < plane.size(); ++i) out.pixels[i * 3 + size_t(c)] = float(plane[i]);
  }
  return out;
}

FloatImage ycxczToHuntLab(const FloatImage& ycxcz) {
  FloatImage out = blankLike(ycxcz, 3);
  for (size_t i = 0; i < size_t(ycxcz.width) * size_t(ycxcz.height); ++i)
    huntLabPixel(&ycxcz.pixels[i * 3], &out.pixels[i * 3]);
  return out;
}

FloatImage colorErrorMap(const FloatImage& referenceLab, const FloatImage& testLab) {
  requireSameSize(referenceLab, testLab);
  FloatImage out = blankLike(referenceLab, 1);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = colorErrorPixel(&referenceLab.pixels[i * 3], &testLab.pixels[i * 3]);
  return out;
}

FeatureMaps detectFeatures(const FloatImage& ycxcz, double pixelsPerDegree) {
  std::vector<double> y = channelOf(ycxcz, 0);
  for (double& v : y) v = featureLuminance(v);
  FeatureMaps maps{blankLike(ycxcz, 1), blankLike(ycxcz, 1)};
  for (FeatureKind kind : {FeatureKind::Edge, FeatureKind::Point}) {
    const KernelTerm alongX = featureKernel(kind, pixelsPerDegree);
    const std::vector<double> dx = filterPlane(y, ycxcz.width, ycxcz.height, {alongX});
    const std::vector<double> dy = filterPlane(y, ycxcz.width, ycxcz.height, {transposed(alongX)});
    FloatImage& map = kind == FeatureKind::Edge ? maps.edges : maps.points;
    for (size_t i = 0; i < y.size(); ++i) map.pixels[i] = float(std::hypot(dx[i], dy[i]));
  }
  return maps;
}

FloatImage featureErrorMap(const FeatureMaps& reference, const FeatureMaps& test) {
  requireSameSize(reference.edges, test.edges);
  FloatImage out = blankLike(reference.edges, 1);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = featureErrorPixel(reference.edges.pixels[i], reference.points.pixels[i], test.edges.pixels[i],
                                      test.points.pixels[i]);
  return out;
}

FloatImage flipErrorMap(int width, int height, const SrgbRows& reference, const SrgbRows& test, int bands,
                        int tileColumns) {
  FloatImage error{width, height, 1, std::vector<float>(size_t(width) * size_t(height))};
  bands = std::clamp(bands > 0 ? bands : flipBandCount(height), 1, std::max(1, height));
  const int columns = std::max(1, tileColumns), tiles = std::max(1, (width + columns - 1) / columns);
  forEachRowInParallel(bands * tiles, 0, [&](int unit) {
    const int band = unit / tiles, x0 = unit % tiles * columns;
    flipTile(reference, test, int(int64_t(height) * band / bands), int(int64_t(height) * (band + 1) / bands), x0,
             std::min(width, x0 + columns), &error);
  });
  return error;
}

FloatImage flipErrorMap(const FloatImage& referenceSrgb, const FloatImage& testSrgb) {
  requireSameSize(referenceSrgb, testSrgb);
  return flipErrorMap(referenceSrgb.width, referenceSrgb.height, imageRows(referenceSrgb), imageRows(testSrgb));
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
