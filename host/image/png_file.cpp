#include "png_file.h"

#include "error.h"

#include <algorithm>
#include <csetjmp>
#include <cstring>

#include <png.h>
#include <zlib.h>

namespace {

const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr size_t kIhdrEnd = 8 + 4 + 4 + 13 + 4;  // signature, then IHDR's length, type, data, CRC
constexpr size_t kIdatBytes = 1 << 20;           // compressed bytes per IDAT chunk

uint32_t bigEndian32(const uint8_t* b) {
  return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}

// libpng: errors end the decode by a longjmp with the message; warnings (about ancillary
// chunks, which raytex does not use) are dropped; nothing is printed.
struct PngErrors {
  char message[256];
};

[[noreturn]] void pngFail(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  snprintf(errors->message, sizeof(errors->message), "%s", message);
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

void pngRead(png_structp png, png_bytep data, size_t length) {
  if (fread(data, 1, length, static_cast<FILE*>(png_get_io_ptr(png))) != length) png_error(png, "the file ends early");
}

// The transforms that turn any non-palette PNG into 8-bit RGBA as stored (no gamma applied;
// 16-bit channels keep their high byte).
void setRgbaTransforms(png_structp png, png_infop info) {
  png_byte colorType = png_get_color_type(png, info);
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  if (!(colorType & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS))
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
}

// 16-bit RGB as stored, in host byte order.
void setRgb16Transforms(png_structp png) {
  png_set_gray_to_rgb(png);
  png_set_strip_alpha(png);
  png_set_swap(png);  // PNG stores 16-bit values big-endian
}

// Palette PNGs are read as one index per byte at the start of each RGBA row, checked against
// the palette's length (libpng itself maps an index past the palette to whatever memory
// follows it), then expanded from the end of the row backwards.
bool expandPalette(png_structp png, png_infop info, uint8_t* rgba, int width, int height, std::string* message) {
  png_colorp palette = nullptr;
  int paletteSize = 0;
  png_get_PLTE(png, info, &palette, &paletteSize);
  png_bytep alpha = nullptr;
  int alphaCount = 0;
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_get_tRNS(png, info, &alpha, &alphaCount, nullptr);
  for (int y = 0; y < height; ++y) {
    uint8_t* row = rgba + size_t(y) * width * 4;
    for (int x = 0; x < width; ++x)
      if (row[x] >= paletteSize) {
        *message = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") uses colour " +
                   std::to_string(row[x]) + " of a palette of " + std::to_string(paletteSize);
        return false;
      }
    for (int x = width - 1; x >= 0; --x) {
      const int index = row[x];
      uint8_t* p = row + size_t(x) * 4;
      p[3] = index < alphaCount ? alpha[index] : 255;
      p[2] = palette[index].blue;
      p[1] = palette[index].green;
      p[0] = palette[index].red;
    }
  }
  return true;
}

// Sets the transforms to `depth` (8: RGBA8, 16: RGB16) and reads the rows; true when the image
// was a palette one, to expand. Runs under decodePng's setjmp: errors are png_error's.
bool readRows(png_structp png, png_infop info, int width, int height, int depth, png_bytep* rows) {
  png_read_info(png, info);
  if (int(png_get_image_width(png, info)) != width || int(png_get_image_height(png, info)) != height)
    png_error(png, "the file changed while it was read");
  const bool palette = depth == 8 && png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE;
  if (palette) png_set_packing(png);  // 1, 2 and 4-bit indices: one byte each
  else if (depth == 8) setRgbaTransforms(png, info);
  else setRgb16Transforms(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const size_t rowBytes = size_t(width) * (palette ? 1 : depth == 8 ? 4 : 6);
  if (png_get_rowbytes(png, info) != rowBytes || (depth == 16 && png_get_bit_depth(png, info) != 16))
    png_error(png, depth == 8 ? "unexpected row layout after conversion to RGBA" : "unexpected row layout after conversion to 16-bit RGB");
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return palette;
}

void appendBigEndian32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

// A chunk: length, type, data, and the CRC of type and data.
void appendChunk(std::vector<uint8_t>& out, const char* type, const uint8_t* data, size_t size) {
  appendBigEndian32(out, uint32_t(size));
  const size_t typeAt = out.size();
  out.insert(out.end(), type, type + 4);
  if (size > 0) out.insert(out.end(), data, data + size);
  appendBigEndian32(out, uint32_t(crc32(0, out.data() + typeAt, uInt(size + 4))));
}

// Row y of an RGB image as the PNG stores it: the filter type (1, sub: each byte minus the byte
// one pixel before it), then the samples, 16-bit ones big-endian.
void filterRow(const void* samples, int width, int depth, int y, std::vector<uint8_t>& out) {
  const size_t pixelBytes = depth == 8 ? 3 : 6, n = size_t(width) * pixelBytes;
  out.assign(n + 1, 1);
  if (depth == 8) {
    memcpy(out.data() + 1, static_cast<const uint8_t*>(samples) + size_t(y) * n, n);
  } else {
    const uint16_t* row = static_cast<const uint16_t*>(samples) + size_t(y) * width * 3;
    for (size_t i = 0; i < size_t(width) * 3; ++i) {
      out[1 + i * 2] = uint8_t(row[i] >> 8);
      out[2 + i * 2] = uint8_t(row[i]);
    }
  }
  for (size_t i = n; i > pixelBytes; --i) out[i] = uint8_t(out[i] - out[i - pixelBytes]);
}

// The zlib stream of the filtered rows, deflated at level 1: with the sub filter, several times
// faster than a per-row choice of filter, into files about as small (docs/performance.md,
// "Start-up", PNG). Empty when deflate fails.
std::vector<uint8_t> deflateRows(const void* samples, int width, int height, int depth) {
  z_stream z{};
  if (deflateInit(&z, Z_BEST_SPEED) != Z_OK) throw Error(ErrorKind::OutOfMemory, "out of memory");
  std::vector<uint8_t> out, row, buffer(1 << 16);
  int status = Z_OK;
  for (int y = 0; y <= height && status != Z_STREAM_ERROR; ++y) {
    const bool last = y == height;
    if (!last) filterRow(samples, width, depth, y, row);
    z.next_in = last ? nullptr : row.data();
    z.avail_in = last ? 0 : uInt(row.size());
    do {
      z.next_out = buffer.data();
      z.avail_out = uInt(buffer.size());
      status = deflate(&z, last ? Z_FINISH : Z_NO_FLUSH);
      out.insert(out.end(), buffer.data(), buffer.data() + (buffer.size() - z.avail_out));
    } while (status != Z_STREAM_ERROR && (z.avail_out == 0 || (last && status != Z_STREAM_END)));
  }
  deflateEnd(&z);
  if (status != Z_STREAM_END) out.clear();
  return out;
}

// The data of a text chunk for one key and value, and its type: tEXt for ASCII, else iTXt
// (no compression, no language, the value as UTF-8).
std::vector<uint8_t> textChunk(const std::string& key, const std::string& value, const char** type) {
  const bool ascii = std::all_of(value.begin(), value.end(), [](char c) { return uint8_t(c) < 0x80; });
  std::vector<uint8_t> data(key.begin(), key.end());
  data.push_back(0);
  if (!ascii) data.insert(data.end(), {0, 0, 0, 0});  // compression flag and method, two empty names
  data.insert(data.end(), value.begin(), value.end());
  *type = ascii ? "tEXt" : "iTXt";
  return data;
}

}  // namespace

bool isPng(const uint8_t* bytes, size_t n) { return n >= 8 && memcmp(bytes, kSignature, 8) == 0; }

bool readPngHeader(FILE* file, const std::string& path, int* width, int* height, int* depth, std::string* error) {
  uint8_t ihdr[25];
  if (fread(ihdr, 1, sizeof(ihdr), file) != sizeof(ihdr) || bigEndian32(ihdr) != 13 ||
      memcmp(ihdr + 4, "IHDR", 4) != 0) {
    *error = "cannot decode image '" + path + "': the PNG header (IHDR) is missing or malformed";
    return false;
  }
  uint32_t w = bigEndian32(ihdr + 8), h = bigEndian32(ihdr + 12);
  if (w == 0 || h == 0 || w > 0x7fffffffu || h > 0x7fffffffu) {
    *error = "cannot decode image '" + path + "': the PNG header gives a size of " + std::to_string(w) + "x" +
             std::to_string(h);
    return false;
  }
  *width = int(w);
  *height = int(h);
  *depth = ihdr[16];
  return true;
}

bool decodePng(FILE* file, int width, int height, int depth, void* out, std::string* message) {
  PngErrors errors{};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, pngFail, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  // Made before setjmp: nothing that longjmp may skip back over allocates.
  const size_t rowBytes = size_t(width) * (depth == 8 ? 4 : 6);
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = static_cast<png_bytep>(out) + y * rowBytes;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    *message = "out of memory";
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    *message = errors.message;
    return false;
  }
  png_set_read_fn(png, file, pngRead);
  png_set_user_limits(png, kMaxImageFileSide, kMaxImageFileSide);
  const bool palette = readRows(png, info, width, height, depth, rows.data());
  const bool ok = !palette || expandPalette(png, info, static_cast<uint8_t*>(out), width, height, message);
  png_destroy_read_struct(&png, &info, nullptr);
  return ok;
}

std::vector<uint8_t> encodePng(const void* samples, int width, int height, int depth) {
  std::vector<uint8_t> png(kSignature, kSignature + 8);
  std::vector<uint8_t> ihdr;
  appendBigEndian32(ihdr, uint32_t(width));
  appendBigEndian32(ihdr, uint32_t(height));
  ihdr.insert(ihdr.end(), {uint8_t(depth), 2, 0, 0, 0});  // RGB, deflate, adaptive filters, no interlace
  appendChunk(png, "IHDR", ihdr.data(), ihdr.size());
  const std::vector<uint8_t> idat = deflateRows(samples, width, height, depth);
  if (idat.empty()) return {};
  for (size_t at = 0; at < idat.size(); at += kIdatBytes)
    appendChunk(png, "IDAT", idat.data() + at, std::min(kIdatBytes, idat.size() - at));
  appendChunk(png, "IEND", nullptr, 0);
  return png;
}

std::vector<uint8_t> encodePng(const ImageRGBA8& image) {
  std::vector<uint8_t> rgb(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i) memcpy(&rgb[i * 3], &image.pixels[i * 4], 3);
  return encodePng(rgb.data(), image.width, image.height, 8);
}

void insertPngText(std::vector<uint8_t>& png, const PngText& text) {
  if (text.empty()) return;
  if (png.size() < kIhdrEnd || !isPng(png.data(), png.size()) || memcmp(png.data() + 12, "IHDR", 4) != 0)
    throw Error(ErrorKind::Internal, "a PNG without IHDR first");
  std::vector<uint8_t> chunks;
  for (const auto& [key, value] : text) {
    const char* type = nullptr;
    const std::vector<uint8_t> data = textChunk(key, value, &type);
    appendChunk(chunks, type, data.data(), data.size());
  }
  png.insert(png.begin() + kIhdrEnd, chunks.begin(), chunks.end());
}
