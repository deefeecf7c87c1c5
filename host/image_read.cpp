#include "image_read.h"

#include "error.h"
#include "float_input.h"
#include "image_io.h"
#include "image_load.h"

#include <cctype>
#include <cstdio>

namespace {

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Refuses an image whose linear RGB floats would take more than maxBytes.
void checkBudget(const std::string& path, int width, int height, uint64_t maxBytes) {
  const uint64_t bytes = uint64_t(width) * uint64_t(height) * 3 * sizeof(float);
  if (bytes <= maxBytes) return;
  char sizes[96];
  snprintf(sizes, sizeof sizes, "%.1f MiB, more than the %.1f MiB allowed", double(bytes) / (1 << 20),
           double(maxBytes) / (1 << 20));
  throw ImageInputError("image '" + path + "' is " + std::to_string(width) + "x" + std::to_string(height) +
                        ": its linear floats would take " + sizes);
}

// PNG and JPEG through loadImage: 8-bit sRGB decoded to linear, alpha dropped.
LinearImage readEightBit(const std::string& path, uint64_t maxBytes) {
  const ImageHeader header = probeImage(path);
  checkBudget(path, header.width, header.height, maxBytes);
  const ImageRGBA8 rgba = loadImage(path);
  float decode[256];
  for (int i = 0; i < 256; ++i) decode[i] = float(srgbToLinear(i / 255.0));
  LinearImage out;
  out.lowDynamicRange = true;
  out.image.width = rgba.width;
  out.image.height = rgba.height;
  out.image.channels = 3;
  out.image.pixels.resize(size_t(rgba.width) * size_t(rgba.height) * 3);
  for (size_t i = 0; i < size_t(rgba.width) * size_t(rgba.height); ++i)
    for (size_t c = 0; c < 3; ++c) out.image.pixels[i * 3 + c] = decode[rgba.pixels[i * 4 + c]];
  return out;
}

}  // namespace

LinearImage readLinearImage(const std::string& path, uint64_t maxBytes) {
  const std::string ext = lowerExtension(path);
  // EXR and PFM hold linear values as stored, of high dynamic range.
  if (ext == "exr") return LinearImage{readExr(path, maxBytes), false};
  if (ext == "pfm") return LinearImage{readPfm(path, maxBytes), false};
  // Every other name goes to the PNG and JPEG reader, which names what it refuses.
  return readEightBit(path, maxBytes);
}
