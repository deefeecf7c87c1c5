#include "png_output.h"

#include "error.h"
#include "image_io.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <zlib.h>

namespace {

const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr size_t kIhdrEnd = 8 + 4 + 4 + 13 + 4;  // signature, then IHDR's length, type, data, CRC
constexpr size_t kIdatBytes = 1 << 20;           // compressed bytes per IDAT chunk

void appendBigEndian32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

// A chunk: length, type, data, and the CRC of type and data.
void appendChunk(std::vector<uint8_t>& out, const char* type, const uint8_t* data, size_t size) {
  appendBigEndian32(out, uint32_t(size));
  const size_t typeAt = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  appendBigEndian32(out, uint32_t(crc32(0, out.data() + typeAt, uInt(size + 4))));
}

// Row y of a 16-bit RGB image as the PNG stores it: the filter type (1, sub: each byte minus
// the byte 6 before it), then big-endian samples.
void filterRow16(const uint16_t* row, int width, std::vector<uint8_t>& out) {
  const size_t n = size_t(width) * 6;
  out.assign(n + 1, 1);
  for (size_t i = 0; i < size_t(width) * 3; ++i) {
    out[1 + i * 2] = uint8_t(row[i] >> 8);
    out[2 + i * 2] = uint8_t(row[i]);
  }
  for (size_t i = n; i > 6; --i) out[i] = uint8_t(out[i] - out[i - 6]);
}

// The zlib stream of the filtered rows, deflated at level 1 (as encodePng does).
std::vector<uint8_t> deflateRows16(const std::vector<uint16_t>& rgb, int width, int height) {
  z_stream z{};
  if (deflateInit(&z, Z_BEST_SPEED) != Z_OK) throw Error(ErrorKind::OutOfMemory, "out of memory");
  std::vector<uint8_t> out, row, buffer(1 << 16);
  int status = Z_OK;
  for (int y = 0; y <= height && status != Z_STREAM_ERROR; ++y) {
    const bool last = y == height;
    if (!last) filterRow16(rgb.data() + size_t(y) * width * 3, width, row);
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
  if (status != Z_STREAM_END) out.clear();  // the caller reports a PNG it cannot encode
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

struct PngSink : BandSink {
  PngSink(const std::string& path, int width, int height, int depth, int source, int channels,
          const Metadata& metadata)
      : file(path), width(width), height(height), depth(depth), source(source), channels(channels),
        metadata(metadata) {
    if (depth == 8) image8 = ImageRGBA8{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
    if (depth == 16) image16.resize(size_t(width) * height * 3);
  }

  void write(const Band& band) override {
    const float* rgba = rgbaOf(band);
    if (depth == 8) {
      size_t bad = 0;
      const ImageRGBA8 part = encodeSrgb(rgba, width, band.rows, &bad);
      std::copy(part.pixels.begin(), part.pixels.end(), image8.pixels.begin() + size_t(band.firstRow) * width * 4);
      badValues += bad;
      return;
    }
    uint16_t* out = image16.data() + size_t(band.firstRow) * width * 3;
    for (size_t i = 0; i < size_t(band.rows) * width; ++i)
      for (int c = 0; c < 3; ++c) {
        badValues += !std::isfinite(rgba[i * 4 + c]);
        out[i * 3 + c] = srgb16(rgba[i * 4 + c]);
      }
  }

  void complete() override {
    std::vector<uint8_t> png = depth == 8 ? encodePng(image8) : encodePng16(image16, width, height);
    if (png.empty()) throw Error(ErrorKind::Internal, "cannot encode PNG for '" + file.path() + "'");
    image8.pixels = {};
    image16 = {};
    insertPngText(png, metadata);
    file.write(png);
  }

  void commit() override { file.commit(); }
  void withdraw() override { file.withdraw(); }
  size_t nonFinite() const override { return badValues; }

  // The band's plane as RGBA: as it is for three channels, else spread into `scratch`.
  const float* rgbaOf(const Band& band) {
    const float* plane = band.plane(source);
    if (channels == 3) return plane;
    scratch.assign(size_t(band.rows) * width * 4, 0.0f);
    for (size_t i = 0; i < size_t(band.rows) * width; ++i) {
      scratch[i * 4] = plane[i * 4];
      scratch[i * 4 + 1] = plane[i * 4 + (channels == 1 ? 0 : 1)];
      scratch[i * 4 + 2] = channels == 1 ? plane[i * 4] : 0.0f;
    }
    return scratch.data();
  }

  OutputFile file;
  int width, height, depth, source, channels;
  Metadata metadata;
  ImageRGBA8 image8;
  std::vector<uint16_t> image16;  // RGB
  std::vector<float> scratch;
  size_t badValues = 0;
};

}  // namespace

uint16_t srgb16(float linear) {
  if (!std::isfinite(linear)) return 0;
  const double v = std::min(std::max(double(linear), 0.0), 1.0);
  return uint16_t(std::lround(linearToSrgb(v) * 65535.0));
}

std::vector<uint8_t> encodePng16(const std::vector<uint16_t>& rgb, int width, int height) {
  std::vector<uint8_t> png(kSignature, kSignature + 8);
  std::vector<uint8_t> ihdr;
  appendBigEndian32(ihdr, uint32_t(width));
  appendBigEndian32(ihdr, uint32_t(height));
  ihdr.insert(ihdr.end(), {16, 2, 0, 0, 0});  // 16 bits, RGB, deflate, adaptive filters, no interlace
  appendChunk(png, "IHDR", ihdr.data(), ihdr.size());
  const std::vector<uint8_t> idat = deflateRows16(rgb, width, height);
  if (idat.empty()) return {};
  for (size_t at = 0; at < idat.size(); at += kIdatBytes)
    appendChunk(png, "IDAT", idat.data() + at, std::min(kIdatBytes, idat.size() - at));
  appendChunk(png, "IEND", nullptr, 0);
  return png;
}

void insertPngText(std::vector<uint8_t>& png, const Metadata& metadata) {
  if (metadata.empty()) return;
  if (png.size() < kIhdrEnd || memcmp(png.data(), kSignature, 8) != 0 || memcmp(png.data() + 12, "IHDR", 4) != 0)
    throw Error(ErrorKind::Internal, "a PNG without IHDR first");
  std::vector<uint8_t> chunks;
  for (const auto& [key, value] : metadata) {
    const char* type = nullptr;
    const std::vector<uint8_t> data = textChunk(key, value, &type);
    appendChunk(chunks, type, data.data(), data.size());
  }
  png.insert(png.begin() + kIhdrEnd, chunks.begin(), chunks.end());
}

std::unique_ptr<BandSink> makePngSink(const std::string& path, int width, int height, int depth, int source,
                                      int channels, const Metadata& metadata) {
  return std::make_unique<PngSink>(path, width, height, depth, source, channels, metadata);
}
