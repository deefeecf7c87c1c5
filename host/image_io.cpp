#include "image_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb_image_resize.h>

bool loadImage(const std::string& path, ImageRGBA8* image, std::string* error) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) {
    FILE* f = fopen(path.c_str(), "rb");
    if (!f) {
      *error = std::string("cannot open image '") + path + "': " + strerror(errno);
    } else {
      fclose(f);
      *error = std::string("cannot decode image '") + path + "': " + stbi_failure_reason();
    }
    return false;
  }
  image->width = w;
  image->height = h;
  image->pixels.assign(data, data + size_t(w) * h * 4);
  stbi_image_free(data);
  return true;
}

ImageRGBA8 resizeImage(const ImageRGBA8& image, int width, int height) {
  if (image.width == width && image.height == height) return image;
  ImageRGBA8 out;
  out.width = width;
  out.height = height;
  out.pixels.resize(size_t(width) * height * 4);
  stbir_resize_uint8_srgb(image.pixels.data(), image.width, image.height, 0, out.pixels.data(),
                          width, height, 0, 4, 3, 0);
  return out;
}

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

namespace {
void appendBytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<uint8_t>*>(context);
  bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}
}  // namespace

void writePngAtomic(const std::string& path, const ImageRGBA8& image) {
  // Drop alpha (always opaque): RGB PNGs are a quarter smaller and faster to encode.
  std::vector<uint8_t> rgb(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
    memcpy(&rgb[i * 3], &image.pixels[i * 4], 3);
  std::vector<uint8_t> png;
  if (!stbi_write_png_to_func(appendBytes, &png, image.width, image.height, 3, rgb.data(),
                              image.width * 3))
    throw std::runtime_error("cannot encode PNG for '" + path + "'");

  std::string tmp = path + ".tmp-XXXXXX";
  int fd = mkstemp(tmp.data());
  if (fd < 0) throw std::runtime_error("cannot write '" + path + "': " + strerror(errno));
  size_t written = 0;
  while (written < png.size()) {
    ssize_t n = write(fd, png.data() + written, png.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      int err = n < 0 ? errno : EIO;
      close(fd);
      unlink(tmp.c_str());
      throw std::runtime_error("cannot write '" + path + "': " + strerror(err));
    }
    written += size_t(n);
  }
  // mkstemp creates 0600; give the image the usual permissions.
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  if (close(fd) != 0 || rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    unlink(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + strerror(err));
  }
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
