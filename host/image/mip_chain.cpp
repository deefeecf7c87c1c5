#include "mip_chain.h"

#include "srgb.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace {

// Linear [0, 1] -> the nearest sRGB code value, round(linearToSrgb(v) * 255), exactly: a table
// gives a guess within one code, and the linear values of the midpoints between codes settle it.
struct SrgbEncoder {
  static constexpr int kSteps = 4096;
  float midpoints[256];  // linear value where code i turns into code i + 1 (the last: above 1)
  uint8_t guess[kSteps + 1];
  SrgbEncoder() {
    for (int i = 0; i < 255; ++i) midpoints[i] = float(srgbToLinear((i + 0.5) / 255.0));
    midpoints[255] = 2.0f;
    for (int i = 0; i <= kSteps; ++i) guess[i] = uint8_t(std::lround(linearToSrgb(double(i) / kSteps) * 255.0));
  }
  uint8_t operator()(float v) const {
    v = std::min(std::max(v, 0.0f), 1.0f);
    int c = guess[int(v * kSteps + 0.5f)];
    while (c > 0 && v < midpoints[c - 1]) --c;
    while (c < 255 && v >= midpoints[c]) ++c;
    return uint8_t(c);
  }
};

// Area-weighted box reduction along one axis: destination texel i covers source texels
// [i r, (i + 1) r), r = from / to, with fractional weights at the ends (exact for odd sizes).
struct AxisWeights {
  std::vector<int> first;       // first source texel of each destination texel
  std::vector<float> weights;   // per destination texel: `span` weights from `first`
  int span = 0;
};

AxisWeights axisWeights(int from, int to) {
  AxisWeights a;
  double r = double(from) / to;
  a.span = int(std::ceil(r)) + 1;
  a.first.resize(size_t(to));
  a.weights.assign(size_t(to) * a.span, 0.0f);
  for (int i = 0; i < to; ++i) {
    double lo = i * r, hi = (i + 1) * r;
    int j0 = int(std::floor(lo));
    a.first[size_t(i)] = j0;
    for (int k = 0; k < a.span; ++k) {
      int j = j0 + k;
      if (j >= from) break;
      double overlap = std::min(hi, j + 1.0) - std::max(lo, double(j));
      if (overlap > 0.0) a.weights[size_t(i) * a.span + k] = float(overlap / r);
    }
  }
  return a;
}

// One level of a mip chain made from the rows of the level below as they come, so that no
// level is ever whole in float: each output texel is the same sum, in the same order, as a
// whole-level reduction would compute. Dimensions halving exactly average 2x2 texels; others
// use area weights (axisWeights), columns first, then rows.
struct RowReducer {
  int inWidth = 0, inHeight = 0, width = 0, height = 0;
  bool even = false;
  AxisWeights wx, wy;
  std::vector<float> pairFirst;  // even: the first row of the current pair
  std::vector<float> columns;    // weighted: the current input row reduced along x
  std::deque<std::pair<int, std::vector<float>>> open;  // weighted: output rows being summed
  int nextRow = 0, nextOpen = 0;
};

RowReducer rowReducer(int inWidth, int inHeight, int width, int height) {
  RowReducer r;
  r.inWidth = inWidth;
  r.inHeight = inHeight;
  r.width = width;
  r.height = height;
  r.even = inWidth == 2 * width && inHeight == 2 * height;
  if (!r.even) {
    r.wx = axisWeights(inWidth, width);
    r.wy = axisWeights(inHeight, height);
    r.columns.resize(size_t(width) * 4);
  }
  return r;
}

void encodeRow(const float* rgba, int width, uint8_t* out) {
  static const SrgbEncoder encodeSrgbCode;
  for (size_t i = 0; i < size_t(width) * 4; i += 4) {
    for (int c = 0; c < 3; ++c) out[i + c] = encodeSrgbCode(rgba[i + c]);
    out[i + 3] = uint8_t(std::lround(std::min(std::max(rgba[i + 3], 0.0f), 1.0f) * 255.0f));
  }
}

// The input row's sums along x (weighted reducers).
void reduceColumns(RowReducer& r, const float* row) {
  for (int x = 0; x < r.width; ++x) {
    float* o = &r.columns[size_t(x) * 4];
    std::fill(o, o + 4, 0.0f);
    for (int k = 0; k < r.wx.span; ++k) {
      float w = r.wx.weights[size_t(x) * r.wx.span + k];
      if (w == 0.0f) continue;
      const float* p = row + size_t(r.wx.first[size_t(x)] + k) * 4;
      for (int c = 0; c < 4; ++c) o[c] += w * p[c];
    }
  }
}

// Feeds one row (linear RGBA floats) to level `l` of the chain; each finished output row is
// encoded into out[l] and fed to the next level.
void pushRow(std::vector<RowReducer>& chain, size_t l, const float* row, uint8_t* const* out) {
  RowReducer& r = chain[l];
  const int j = r.nextRow++;
  auto emit = [&](int y, const float* texels) {
    encodeRow(texels, r.width, out[l] + size_t(y) * r.width * 4);
    if (l + 1 < chain.size()) pushRow(chain, l + 1, texels, out);
  };
  if (r.even) {
    if (j % 2 == 0) {
      r.pairFirst.assign(row, row + size_t(r.inWidth) * 4);
      return;
    }
    std::vector<float> texels(size_t(r.width) * 4);
    const float* r0 = r.pairFirst.data();
    for (int x = 0; x < r.width; ++x)
      for (int c = 0; c < 4; ++c) {
        size_t a = size_t(2 * x) * 4 + c, b = a + 4;
        texels[size_t(x) * 4 + c] = 0.25f * ((r0[a] + r0[b]) + (row[a] + row[b]));
      }
    emit(j / 2, texels.data());
    return;
  }
  reduceColumns(r, row);
  while (r.nextOpen < r.height && r.wy.first[size_t(r.nextOpen)] <= j)
    r.open.emplace_back(r.nextOpen++, std::vector<float>(size_t(r.width) * 4, 0.0f));
  for (auto& [y, sum] : r.open) {
    int k = j - r.wy.first[size_t(y)];
    float w = k < r.wy.span ? r.wy.weights[size_t(y) * r.wy.span + k] : 0.0f;
    if (w == 0.0f) continue;
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += w * r.columns[i];
  }
  while (!r.open.empty() &&
         (r.wy.first[size_t(r.open.front().first)] + r.wy.span - 1 <= j || j == r.inHeight - 1)) {
    emit(r.open.front().first, r.open.front().second.data());
    r.open.pop_front();
  }
}

}  // namespace

int mipLevelCount(int width, int height) {
  int levels = 1;
  for (int size = std::max(width, height); size > 1; size >>= 1) ++levels;
  return levels;
}

std::vector<ImageRGBA8> mipChain(const ImageRGBA8& image) { return mipChain(ImageRGBA8(image)); }

std::vector<ImageRGBA8> mipChain(ImageRGBA8&& level0) {
  const int width = level0.width, height = level0.height;
  std::vector<ImageRGBA8> chain;
  chain.reserve(size_t(mipLevelCount(width, height)));
  chain.push_back(std::move(level0));
  std::vector<uint8_t*> out;
  for (int l = 1; l < mipLevelCount(width, height); ++l) {
    chain.push_back({std::max(1, width >> l), std::max(1, height >> l), {}});
    chain.back().pixels.resize(size_t(chain.back().width) * chain.back().height * 4);
    out.push_back(chain.back().pixels.data());
  }
  writeMipLevels(chain[0].pixels.data(), width, height, out.data());
  return chain;
}

void writeMipLevels(const uint8_t* pixels, int width, int height, uint8_t* const* out) {
  const int levels = mipLevelCount(width, height);
  if (width <= 0 || height <= 0 || levels == 1) return;
  std::vector<RowReducer> chain;
  for (int l = 1; l < levels; ++l)
    chain.push_back(rowReducer(std::max(1, width >> (l - 1)), std::max(1, height >> (l - 1)),
                               std::max(1, width >> l), std::max(1, height >> l)));
  const float* decode = srgbDecodeTable();
  std::vector<float> row(size_t(width) * 4);
  for (int y = 0; y < height; ++y) {
    const uint8_t* p = pixels + size_t(y) * width * 4;
    for (size_t i = 0; i < row.size(); i += 4) {
      for (int c = 0; c < 3; ++c) row[i + c] = decode[p[i + c]];
      row[i + 3] = p[i + 3] / 255.0f;
    }
    pushRow(chain, 0, row.data(), out);
  }
}

