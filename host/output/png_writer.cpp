#include "png_writer.h"

#include "error.h"
#include "png_file.h"
#include "srgb.h"

#include <algorithm>
#include <cmath>


namespace {

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
    std::vector<uint8_t> png = depth == 8 ? encodePng(image8) : encodePng(image16.data(), width, height, 16);
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

  AtomicFile file;
  int width, height, depth, source, channels;
  Metadata metadata;
  ImageRGBA8 image8;
  std::vector<uint16_t> image16;  // RGB
  std::vector<float> scratch;
  size_t badValues = 0;
};

}  // namespace

std::unique_ptr<BandSink> makePngSink(const std::string& path, int width, int height, int depth, int source,
                                      int channels, const Metadata& metadata) {
  return std::make_unique<PngSink>(path, width, height, depth, source, channels, metadata);
}
