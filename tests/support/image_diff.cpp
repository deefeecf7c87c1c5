#include "support/image_diff.h"

#include <algorithm>
#include <cstdlib>

#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb_image_resize.h>

ImageRGBA8 resizeImage(const ImageRGBA8& image, int width, int height) {
  if (image.width == width && image.height == height) return image;
  ImageRGBA8 out;
  out.width = width;
  out.height = height;
  out.pixels.resize(size_t(width) * height * 4);
  resizeImage(image, width, height, out.pixels.data());
  return out;
}

void resizeImage(const ImageRGBA8& image, int width, int height, uint8_t* out) {
  if (image.width == width && image.height == height) {
    std::copy(image.pixels.begin(), image.pixels.end(), out);
    return;
  }
  stbir_resize_uint8_srgb(image.pixels.data(), image.width, image.height, 0, out, width, height, 0, 4, 3, 0);
}

ImageDiff compareImages(const ImageRGBA8& a, const ImageRGBA8& b) {
  ImageDiff diff;
  if (a.width != b.width || a.height != b.height) {
    diff.sizeMismatch = true;
    diff.maxError = 255;
    diff.meanError = 255.0;
    return diff;
  }
  double sum = 0.0;
  size_t n = size_t(a.width) * a.height;
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      int d = std::abs(int(a.pixels[i * 4 + c]) - int(b.pixels[i * 4 + c]));
      diff.maxError = std::max(diff.maxError, d);
      sum += d;
    }
  }
  diff.meanError = n ? sum / (3.0 * n) : 0.0;
  return diff;
}

ImageRGBA8 diffImage(const ImageRGBA8& a, const ImageRGBA8& b, int gain) {
  ImageRGBA8 out;
  out.width = std::min(a.width, b.width);
  out.height = std::min(a.height, b.height);
  out.pixels.resize(size_t(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      size_t ia = (size_t(y) * a.width + x) * 4, ib = (size_t(y) * b.width + x) * 4;
      size_t io = (size_t(y) * out.width + x) * 4;
      for (int c = 0; c < 3; ++c)
        out.pixels[io + c] = uint8_t(std::min(255, gain * std::abs(int(a.pixels[ia + c]) - int(b.pixels[ib + c]))));
      out.pixels[io + 3] = 255;
    }
  }
  return out;
}

FloatImage rgbFloatImage(const float* rgba, int width, int height) {
  FloatImage image{width, height, 3, std::vector<float>(size_t(width) * size_t(height) * 3)};
  for (size_t i = 0; i < size_t(width) * size_t(height); ++i)
    for (size_t c = 0; c < 3; ++c) image.pixels[i * 3 + c] = rgba[i * 4 + c];
  return image;
}
