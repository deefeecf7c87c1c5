#include "image_read.h"

#include "error.h"
#include "image_io.h"
#include "image_load.h"
#include "input_file.h"

#include <png.h>

#include <cctype>
#include <csetjmp>
#include <new>
#include <vector>
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

// Whether a PNG file stores 16 bits a channel: byte 24 of the file, IHDR's bit depth. A file
// that cannot be opened as a regular file is not: the 8-bit reader names why.
bool sixteenBitPng(const std::string& path) {
  std::string why;
  FILE* f = openRegularStream(path, &why);
  if (!f) return false;
  unsigned char head[25] = {};
  const bool full = fread(head, 1, sizeof head, f) == sizeof head;
  fclose(f);
  return full && head[24] == 16;
}

struct Png16Errors {
  char message[256] = "";
};

[[noreturn]] void png16Fail(png_structp png, png_const_charp message) {
  snprintf(static_cast<Png16Errors*>(png_get_error_ptr(png))->message, 256, "%s", message);
  png_longjmp(png, 1);
}

// Warnings (about ancillary chunks, which raytex does not use) are dropped, as for 8-bit images
// (image_load.cpp): libpng prints nothing, and errors reach the user as the one line of the refusal.
void png16Warn(png_structp, png_const_charp) {}

void png16Read(png_structp png, png_bytep data, size_t length) {
  if (fread(data, 1, length, static_cast<FILE*>(png_get_io_ptr(png))) != length) png_error(png, "the file ends early");
}

// Decodes a 16-bit PNG (probed by probeImage) into `rgb16`: RGB as stored, host byte order.
void decodePng16(const std::string& path, FILE* file, const ImageHeader& header, std::vector<uint16_t>& rgb16) {
  Png16Errors errors;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, png16Fail, png16Warn);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    throw std::bad_alloc();
  }
  // Sized before setjmp: nothing that longjmp may skip back over allocates.
  rgb16.resize(size_t(header.width) * size_t(header.height) * 3);
  std::vector<png_bytep> rows(size_t(header.height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = reinterpret_cast<png_bytep>(&rgb16[y * size_t(header.width) * 3]);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw ImageInputError("cannot decode image '" + path + "': " + errors.message);
  }
  png_set_read_fn(png, file, png16Read);
  png_set_user_limits(png, kMaxImageFileSide, kMaxImageFileSide);
  png_read_info(png, info);
  if (int(png_get_image_width(png, info)) != header.width || int(png_get_image_height(png, info)) != header.height)
    png_error(png, "the file changed while it was read");
  png_set_gray_to_rgb(png);
  png_set_strip_alpha(png);
  png_set_swap(png);  // PNG stores 16-bit values big-endian
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_bit_depth(png, info) != 16 || png_get_rowbytes(png, info) != size_t(header.width) * 6)
    png_error(png, "unexpected row layout after conversion to 16-bit RGB");
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
}

// A 16-bit PNG at its full precision: sRGB decoded to linear, alpha dropped.
LinearImage readSixteenBit(const std::string& path, uint64_t maxBytes) {
  const ImageHeader header = probeImage(path);
  checkBudget(path, header.width, header.height, maxBytes);
  std::string why;
  FILE* file = openRegularStream(path, &why);
  if (!file) throw ImageInputError("cannot open image '" + path + "': " + why);
  std::vector<uint16_t> rgb16;
  try {
    decodePng16(path, file, header, rgb16);
  } catch (...) {
    fclose(file);
    throw;
  }
  fclose(file);
  std::vector<float> decode(65536);
  for (size_t i = 0; i < decode.size(); ++i) decode[i] = float(srgbToLinear(double(i) / 65535.0));
  LinearImage out{FloatImage{header.width, header.height, 3, std::vector<float>(rgb16.size())}, true};
  for (size_t i = 0; i < rgb16.size(); ++i) out.image.pixels[i] = decode[rgb16[i]];
  return out;
}

}  // namespace

LinearImage readSrgbImage(const std::string& path, uint64_t maxBytes) {
  // The PNG and JPEG readers name what they refuse, whatever the name.
  if (lowerExtension(path) == "png" && sixteenBitPng(path)) return readSixteenBit(path, maxBytes);
  return readEightBit(path, maxBytes);
}
