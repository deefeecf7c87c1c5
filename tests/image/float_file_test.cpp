// readExr and readPfm (host/image/float_file.h): files the writers made read back exactly, files
// written here by the formats' specifications (big-endian PFM, an EXR of Y alone, a data window
// away from the origin) or by OpenEXR's RgbaOutputFile (luminance and chroma), and every kind
// of bad file refused with a message naming it.
#include "float_file.h"
#include "image_metrics.h"
#include "image_writer.h"
#include "output_formats.h"
#include "support/band_images.h"
#include "support/files.h"
#include "support/format.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>

namespace fs = std::filesystem;

namespace {

constexpr uint64_t kBudget = uint64_t(1) << 30;


// The message of the ImageInputError that `read` throws for `path`; "" if it reads the file.
std::string readError(FloatImage (*read)(const std::string&, uint64_t), const fs::path& path,
                      uint64_t budget = kBudget) {
  try {
    read(path.string(), budget);
  } catch (const ImageInputError& e) {
    return e.what();
  }
  return "";
}

// Expects the message to name the file first and to hold `part`.
#define EXPECT_REFUSED(message, path, part)                                         \
  do {                                                                              \
    const std::string m = (message);                                                \
    EXPECT_EQ(m.rfind((path).string() + ": ", 0), 0u) << m;                         \
    EXPECT_NE(m.find(part), std::string::npos) << m;                                \
  } while (0)

void expectColour(const FloatImage& got, const BandImage& image) {
  ASSERT_EQ(got.width, image.width);
  ASSERT_EQ(got.height, image.height);
  ASSERT_EQ(got.channels, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(bitsOf(got.at(x, y, c)), bitsOf(image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4 + size_t(c)]))
            << x << ", " << y << ", " << c;
}

TEST(FloatInput, ReadsBackTheExrAndPfmTheWritersMake) {
  const fs::path dir = freshTempDir("float_input_round_trip");
  const BandImage image = bandImage(37, 21, {Pass::Depth});
  writeBandImage(bandSpec((dir / "a.exr").string(), OutputFormat::Exr, image, {Pass::Depth}), image, 16,
                 BandOrder::TopFirst);
  writeBandImage(bandSpec((dir / "a.pfm").string(), OutputFormat::Pfm, image, {Pass::Depth}), image, 5,
                 BandOrder::BottomFirst);
  expectColour(readExr((dir / "a.exr").string(), kBudget), image);
  expectColour(readPfm((dir / "a.pfm").string(), kBudget), image);
  const FloatImage depth = readPfm((dir / "a.depth.pfm").string(), kBudget);  // "Pf": grey
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 37; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(depth.at(x, y, c), image.passes[0][(size_t(y) * 37 + size_t(x)) * 4]);
}

TEST(FloatInput, ReadsABigEndianPfm) {
  const fs::path dir = freshTempDir("float_input_big_endian");
  const float values[2][2][3] = {{{1.5f, -2.0f, 0.25f}, {3.0f, 4.0f, 5.0f}}, {{-0.5f, 1e10f, 7.0f}, {0.0f, 8.0f, 9.0f}}};
  std::string bytes = "PF\n2 2\n1.0\n";  // a positive scale: big-endian
  for (int fileRow = 0; fileRow < 2; ++fileRow)  // bottom row first
    for (const auto& pixel : values[1 - fileRow])
      for (float v : pixel)
        for (int shift = 24; shift >= 0; shift -= 8) bytes += char(bitsOf(v) >> shift);
  writeFile(dir / "be.pfm", bytes);
  const FloatImage image = readPfm((dir / "be.pfm").string(), kBudget);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(image.at(x, y, c), values[y][x][c]);
}

// An EXR of float channels `names`, its data window at (x0, y0), pixel (x, y) of channel c
// holding x + 100 y + 1000 c.
void writeExrByHand(const fs::path& path, const std::vector<std::string>& names, int x0, int y0, int w, int h) {
  Imf::Header header(Imath::Box2i({x0, y0}, {x0 + w - 1, y0 + h - 1}), Imath::Box2i({x0, y0}, {x0 + w - 1, y0 + h - 1}));
  std::vector<std::vector<float>> planes(names.size(), std::vector<float>(size_t(w * h)));
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    for (int i = 0; i < w * h; ++i) planes[c][size_t(i)] = float(i % w + 100 * (i / w) + 1000 * int(c));
    char* base = reinterpret_cast<char*>(planes[c].data()) - (ptrdiff_t(y0) * w + x0) * ptrdiff_t(sizeof(float));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * size_t(w)));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(h);
}

TEST(FloatInput, ReadsAnExrOfYAloneAsGreyAndADataWindowAwayFromTheOrigin) {
  const fs::path dir = freshTempDir("float_input_exr_by_hand");
  writeExrByHand(dir / "y.exr", {"Y"}, 0, 0, 5, 4);
  const FloatImage grey = readExr((dir / "y.exr").string(), kBudget);
  ASSERT_EQ(grey.width, 5);
  ASSERT_EQ(grey.height, 4);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(grey.at(3, 2, c), 203.0f);
  writeExrByHand(dir / "window.exr", {"B", "G", "R", "Z"}, 7, -3, 6, 5);  // channels are stored by name
  const FloatImage moved = readExr((dir / "window.exr").string(), kBudget);
  ASSERT_EQ(moved.width, 6);
  ASSERT_EQ(moved.height, 5);
  EXPECT_EQ(moved.at(4, 3, 0), 2000.0f + 304.0f);  // R, the third channel written
  EXPECT_EQ(moved.at(4, 3, 1), 1000.0f + 304.0f);
  EXPECT_EQ(moved.at(4, 3, 2), 304.0f);
  writeExrByHand(dir / "depth.exr", {"Z"}, 0, 0, 3, 3);
  EXPECT_REFUSED(readError(readExr, dir / "depth.exr"), dir / "depth.exr", "no R, G and B channels, nor Y");
}

// A smooth colour at pixel (x, y) of a w x h image, linear: luminance/chroma keeps one chroma
// sample for each 2x2 pixels and filters it back, which a smooth image survives.
Imf::Rgba smoothColour(int x, int y, int w, int h) {
  const float u = float(x) / float(w), v = float(y) / float(h);
  return Imf::Rgba(0.8f - 0.5f * u, 0.2f + 0.6f * v, 0.1f + 0.3f * (u + v), 1.0f);
}

// An EXR of smoothColour through OpenEXR's RgbaOutputFile: `channels` WRITE_YCA (Y, RY, BY,
// A, as half, the chroma sampled 2x2) or WRITE_RGBA; its data window at (x0, y0).
void writeRgbaExr(const fs::path& path, Imf::RgbaChannels channels, int x0, int y0, int w, int h) {
  std::vector<Imf::Rgba> pixels;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) pixels.push_back(smoothColour(x, y, w, h));
  const Imath::Box2i window({x0, y0}, {x0 + w - 1, y0 + h - 1});
  Imf::RgbaOutputFile file(path.c_str(), window, window, channels);
  file.setFrameBuffer(pixels.data() - (ptrdiff_t(y0) * w + x0), 1, size_t(w));
  file.writePixels(h);
}

TEST(FloatInput, ReadsALuminanceChromaExrAsItsColour) {
  const fs::path dir = freshTempDir("float_input_yca");
  const int w = 48, h = 36;
  writeRgbaExr(dir / "yca.exr", Imf::WRITE_YCA, -6, 4, w, h);  // the origin even, as 2x2 sampling needs
  writeRgbaExr(dir / "rgb.exr", Imf::WRITE_RGBA, 0, 0, w, h);
  const FloatImage got = readExr((dir / "yca.exr").string(), kBudget);
  ASSERT_EQ(got.width, w);
  ASSERT_EQ(got.height, h);
  // RgbaOutputFile keeps 7 of a half's 10 fraction bits of Y and 5 of the chroma (R - Y) / Y
  // and (B - Y) / Y, which moves R and B by at most 2^-6 |chroma| Y + 2^-8 of themselves: with
  // chroma of at most 1.5 here, 2.7% of the pixel's largest channel, and G (from Y, R and B) by
  // 1.6% (the filters restore a linear gradient). Measured: 2.5%.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Imf::Rgba want = smoothColour(x, y, w, h);
      const float wanted[3] = {want.r, want.g, want.b};
      const float tolerance = 0.03f * std::max({wanted[0], wanted[1], wanted[2]});
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got.at(x, y, c), wanted[c], tolerance) << x << ", " << y << ", " << c;
    }
  // As raytex diff reads and measures them: the half RGB file and its luminance/chroma copy
  // (0.0017; read as grey, Y alone, 0.14).
  const double rmse = rootMeanSquareError(readLinearImage((dir / "rgb.exr").string(), kBudget).image,
                                          readLinearImage((dir / "yca.exr").string(), kBudget).image);
  EXPECT_LT(rmse, 0.005);
}

TEST(FloatInput, ReadsRgbBesideLuminanceChromaAndRefusesChromaItCannotConvert) {
  const fs::path dir = freshTempDir("float_input_yca_bad");
  writeExrByHand(dir / "both.exr", {"R", "G", "B", "Y", "RY", "BY"}, 0, 0, 4, 4);  // RGB wins, as stored
  const FloatImage both = readExr((dir / "both.exr").string(), kBudget);
  EXPECT_EQ(both.at(1, 2, 0), 201.0f);
  EXPECT_EQ(both.at(1, 2, 1), 1201.0f);
  EXPECT_EQ(both.at(1, 2, 2), 2201.0f);
  writeExrByHand(dir / "full.exr", {"Y", "RY", "BY"}, 0, 0, 4, 4);  // chroma at every pixel
  EXPECT_REFUSED(readError(readExr, dir / "full.exr"), dir / "full.exr",
                 "the EXR channel RY is sampled 1x1, which is not supported here (only 2x2)");
  writeExrByHand(dir / "half.exr", {"Y", "RY"}, 0, 0, 4, 4);
  EXPECT_REFUSED(readError(readExr, dir / "half.exr"), dir / "half.exr", "one chroma channel of RY and BY, not both");
}

TEST(FloatInput, RefusesBadPfmFiles) {
  const fs::path dir = freshTempDir("float_input_bad_pfm");
  const BandImage image = bandImage(4, 3, {});
  writeBandImage(bandSpec((dir / "good.pfm").string(), OutputFormat::Pfm, image, {}), image, 3, BandOrder::OneBand);
  const std::string good = readFile(dir / "good.pfm");
  const std::pair<std::string, std::string> cases[] = {
      {"", "the file is empty"},
      {good.substr(0, good.size() - 5), "(it ends early)"},
      {good + "xyz", "the file holds 147 bytes"},
      {"P6\n4 3\n255\n", "neither PF nor Pf"},
      {"\x89PNG\r\n\x1a\n", "neither PF nor Pf"},
      {"PF\n20000 10\n-1.0\n", "20000x10 is over the limit of 16384 pixels a side"},
      {"PF\n4 99999999999999\n-1.0\n", "over the limit of 16384 pixels a side"},
      {"PF\n0 5\n-1.0\n", "its header gives a size of 0x5"},
      {"PF\n4 3\nabc\n", "'abc' is not a scale"},
      {"PF\n4 3\n0\n", "'0' is not a scale"},
      {"PF\n4 -3\n-1.0\n", "'-3' is not a size"},
      {"PF\n4", "malformed or cut short"},
  };
  for (const auto& [bytes, part] : cases) {
    writeFile(dir / "bad.pfm", bytes);
    EXPECT_REFUSED(readError(readPfm, dir / "bad.pfm"), dir / "bad.pfm", part);
  }
  EXPECT_REFUSED(readError(readPfm, dir / "good.pfm", 4 * 3 * 12 - 1), dir / "good.pfm",
                 "4x3 needs 144 bytes as float RGB, over the limit of 143");
  EXPECT_EQ(readError(readPfm, dir / "good.pfm", 4 * 3 * 12), "");
  EXPECT_REFUSED(readError(readPfm, dir / "missing.pfm"), dir / "missing.pfm", "cannot open: No such file");
  EXPECT_REFUSED(readError(readPfm, dir), dir, "not a regular file");
  ASSERT_EQ(mkfifo((dir / "fifo.pfm").c_str(), 0600), 0);
  EXPECT_REFUSED(readError(readPfm, dir / "fifo.pfm"), dir / "fifo.pfm", "not a regular file");
}

// `bytes` with the little-endian 32-bit value of the dataWindow attribute's field `field`
// (0 xMin, 1 yMin, 2 xMax, 3 yMax) set to `value`, found by the attribute's name and type.
std::string withDataWindow(std::string bytes, int field, int32_t value) {
  const std::string key("dataWindow\0box2i\0", 17);
  const size_t at = bytes.find(key);
  if (at == std::string::npos) return "";
  for (int i = 0; i < 4; ++i) bytes[at + key.size() + 4 + size_t(field) * 4 + size_t(i)] = char(uint32_t(value) >> (8 * i));
  return bytes;
}

TEST(FloatInput, RefusesBadExrFiles) {
  const fs::path dir = freshTempDir("float_input_bad_exr");
  BandImage image = bandImage(64, 48, {});
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = float(i % 8) * 0.25f;  // compresses well
  writeBandImage(bandSpec((dir / "good.exr").string(), OutputFormat::Exr, image, {}), image, 48, BandOrder::OneBand);
  const std::string good = readFile(dir / "good.exr");
  std::string corrupt = good;
  for (size_t i = good.size() * 6 / 10; i < good.size() * 7 / 10; ++i) corrupt[i] = char(corrupt[i] ^ 0x5a);
  const std::pair<std::string, std::string> cases[] = {
      {"", "not an EXR file (the file is empty)"},
      {"PF\n4 3\n-1.0\n", "not an EXR file (no EXR magic number)"},
      {good.substr(0, 30), "the EXR header is cut short or corrupt"},
      {good.substr(0, good.size() * 6 / 10), ""},
      {corrupt, ""},
      {withDataWindow(good, 2, 19999), "20000x48 is over the limit of 16384 pixels a side"},
      {withDataWindow(good, 2, -5), "its header gives a size of -4x48"},
      {withDataWindow(good, 3, 0x7fffffff), "over the limit of 16384 pixels a side"},
  };
  for (const auto& [bytes, part] : cases) {
    writeFile(dir / "bad.exr", bytes);
    EXPECT_REFUSED(readError(readExr, dir / "bad.exr"), dir / "bad.exr", part);
  }
  EXPECT_REFUSED(readError(readExr, dir / "good.exr", 64 * 48 * 12 - 1), dir / "good.exr",
                 "64x48 needs 36864 bytes as float RGB, over the limit of 36863");
  EXPECT_EQ(readError(readExr, dir / "good.exr"), "");
  EXPECT_REFUSED(readError(readExr, dir / "missing.exr"), dir / "missing.exr", "cannot open: No such file");
  ASSERT_EQ(mkfifo((dir / "fifo.exr").c_str(), 0600), 0);
  EXPECT_REFUSED(readError(readExr, dir / "fifo.exr"), dir / "fifo.exr", "not a regular file");
}

}  // namespace
