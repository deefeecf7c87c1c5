// Test helper for viewer_test.sh: compares a window captured by xwd (X Window Dump, ZPixmap,
// 24 or 32 bits per pixel, 8-bit channels) with a PNG of the same size.
// Usage: raytex_xwd_diff WINDOW.xwd IMAGE.png MAX_DIFFERENCE
// Prints the largest channel difference; exits 0 if it is at most MAX_DIFFERENCE, 1 if not,
// 2 if a file cannot be read or the sizes differ.
#include "image_file.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

uint32_t bigEndian(const std::vector<uint8_t>& d, size_t field) {
  const uint8_t* p = d.data() + 4 * field;
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

// Header fields of XWDFileHeader (X11/XWDFile.h), 32-bit big-endian words.
enum Field { kHeaderSize = 0, kFormat = 2, kWidth = 4, kHeight = 5, kByteOrder = 7, kBitsPerPixel = 11,
             kBytesPerLine = 12, kRedMask = 14, kNumColors = 19, kFieldCount = 25 };

bool loadXwd(const std::string& path, ImageRGBA8* image, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (d.size() < 4 * kFieldCount) return *error = path + ": not an XWD file", false;
  uint32_t bpp = bigEndian(d, kBitsPerPixel), bytesPerLine = bigEndian(d, kBytesPerLine);
  image->width = int(bigEndian(d, kWidth));
  image->height = int(bigEndian(d, kHeight));
  size_t offset = size_t(bigEndian(d, kHeaderSize)) + size_t(bigEndian(d, kNumColors)) * 12;
  if (bigEndian(d, kFormat) != 2 || (bpp != 24 && bpp != 32) || bigEndian(d, kByteOrder) != 0 ||
      bigEndian(d, kRedMask) != 0xff0000u || offset + size_t(bytesPerLine) * image->height > d.size())
    return *error = path + ": not a 24/32-bit LSB-first RGB ZPixmap", false;
  image->pixels.resize(size_t(image->width) * image->height * 4);
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width; ++x) {
      const uint8_t* p = d.data() + offset + size_t(y) * bytesPerLine + size_t(x) * (bpp / 8);  // B, G, R
      uint8_t* q = image->pixels.data() + (size_t(y) * image->width + x) * 4;
      q[0] = p[2], q[1] = p[1], q[2] = p[0], q[3] = 255;
    }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: %s WINDOW.xwd IMAGE.png MAX_DIFFERENCE\n", argv[0]);
    return 2;
  }
  ImageRGBA8 window, image;
  std::string error;
  if (!loadXwd(argv[1], &window, &error)) {
    fprintf(stderr, "%s\n", error.c_str());
    return 2;
  }
  try {
    image = loadImage(argv[2]);
  } catch (const ImageInputError& e) {
    fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (window.width != image.width || window.height != image.height) {
    fprintf(stderr, "sizes differ: %dx%d window, %dx%d image\n", window.width, window.height, image.width, image.height);
    return 2;
  }
  int largest = 0;
  for (size_t i = 0; i < window.pixels.size(); ++i)
    if (i % 4 != 3) largest = std::max(largest, std::abs(int(window.pixels[i]) - int(image.pixels[i])));
  printf("largest channel difference %d\n", largest);
  return largest <= atoi(argv[3]) ? 0 : 1;
}
