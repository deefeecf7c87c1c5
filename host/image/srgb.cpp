#include "srgb.h"

#include <algorithm>
#include <cmath>
#include <vector>

double srgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

ImageRGBA8 encodeSrgb(const float* rgba, int width, int height, size_t* nonFinite) {
  // 65536-entry table over linear [0, 1]: the steepest slope of the sRGB curve
  // (12.92 * 255 per unit) moves less than 0.03 code values per entry.
  static const std::vector<uint8_t> table = [] {
    std::vector<uint8_t> t(65537);
    for (int i = 0; i <= 65536; ++i) t[i] = uint8_t(std::lround(linearToSrgb(i / 65536.0) * 255.0));
    return t;
  }();
  ImageRGBA8 out;
  out.width = width;
  out.height = height;
  out.pixels.resize(size_t(width) * height * 4);
  size_t bad = 0;
  for (size_t i = 0; i < size_t(width) * height; ++i) {
    for (int c = 0; c < 3; ++c) {
      float v = rgba[i * 4 + c];
      if (!std::isfinite(v)) {
        ++bad;
        v = 0.0f;
      }
      v = std::min(std::max(v, 0.0f), 1.0f);
      out.pixels[i * 4 + c] = table[size_t(v * 65536.0f + 0.5f)];
    }
    out.pixels[i * 4 + 3] = 255;
  }
  if (nonFinite) *nonFinite = bad;
  return out;
}

const float* srgbDecodeTable() {
  static const std::vector<float> table = [] {
    std::vector<float> t(256);
    for (int i = 0; i < 256; ++i) t[size_t(i)] = float(srgbToLinear(i / 255.0));
    return t;
  }();
  return table.data();
}

uint16_t srgb16(float linear) {
  if (!std::isfinite(linear)) return 0;
  const double v = std::min(std::max(double(linear), 0.0), 1.0);
  return uint16_t(std::lround(linearToSrgb(v) * 65535.0));
}
