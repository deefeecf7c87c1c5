// The output writers (image_writer.h, atomic_file.h): the same bytes however the rows come,
// PFM and PNG bytes parsed here by their specifications, EXR read back through OpenEXR, and
// nothing left behind by a writer that does not finish. No device.
#include "png_file.h"
#include "srgb.h"
#include "image_writer.h"
#include "atomic_file.h"
#include "support/band_images.h"
#include "support/files.h"
#include "support/format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <csetjmp>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <thread>

#include <fcntl.h>
#include <png.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

namespace fs = std::filesystem;

namespace {



// The float whose little-endian bytes start at `at`.
float littleEndianFloat(const std::string& bytes, size_t at) {
  uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits |= uint32_t(uint8_t(bytes[at + size_t(i)])) << (8 * i);
  float v;
  memcpy(&v, &bits, 4);
  return v;
}

uint32_t bigEndian32(const std::string& bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = v << 8 | uint8_t(bytes[at + size_t(i)]);
  return v;
}

// The sRGB encoding (IEC 61966-2-1), written out here as the oracle of the PNG writers.
double srgbOracle(double linear) {
  linear = std::min(std::max(linear, 0.0), 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// A PNG decoded by libpng with no conversion: its header, its rows as stored, its text.
struct DecodedPng {
  bool ok = false;
  int width = 0, height = 0, depth = 0, colourType = 0;
  std::vector<uint8_t> pixels;
  std::vector<std::pair<std::string, std::string>> text;
};

struct PngSource {
  const std::string* bytes;
  size_t at;
};

void readFromMemory(png_structp png, png_bytep out, size_t n) {
  auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
  if (source->at + n > source->bytes->size()) png_error(png, "past the end");
  memcpy(out, source->bytes->data() + source->at, n);
  source->at += n;
}

void decodeInto(png_structp png, png_infop info, DecodedPng& out) {
  png_read_info(png, info);
  out.width = int(png_get_image_width(png, info));
  out.height = int(png_get_image_height(png, info));
  out.depth = png_get_bit_depth(png, info);
  out.colourType = png_get_color_type(png, info);
  const size_t rowBytes = png_get_rowbytes(png, info);
  out.pixels.resize(rowBytes * size_t(out.height));
  std::vector<png_bytep> rows;
  for (int y = 0; y < out.height; ++y) rows.push_back(out.pixels.data() + rowBytes * size_t(y));
  png_read_image(png, rows.data());
  png_read_end(png, info);
  png_textp text = nullptr;
  int count = 0;
  png_get_text(png, info, &text, &count);
  for (int i = 0; i < count; ++i) out.text.emplace_back(text[i].key, text[i].text);
  out.ok = true;
}

DecodedPng decodePng(const std::string& bytes) {
  DecodedPng out;
  PngSource source{&bytes, 0};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_set_read_fn(png, &source, readFromMemory);
    decodeInto(png, info, out);
  } else {
    out.ok = false;
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return out;
}

// Every chunk of a PNG: its type and data, and whether its CRC is right.
struct Chunk {
  std::string type, data;
  bool crcOk = false;
};

std::vector<Chunk> chunks(const std::string& png) {
  std::vector<Chunk> out;
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t length = bigEndian32(png, at);
    if (at + 12 + length > png.size()) break;
    Chunk chunk{png.substr(at + 4, 4), png.substr(at + 8, length), false};
    const uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(png.data() + at + 4), uInt(length + 4)));
    chunk.crcOk = crc == bigEndian32(png, at + 8 + length);
    out.push_back(chunk);
    at += 12 + length;
  }
  return out;
}

const std::vector<Pass> kSomePasses = {Pass::Normal, Pass::Depth, Pass::Position, Pass::Albedo, Pass::Footprint};

TEST(ImageWriter, OneBandOrSeveralInAnyOrderGiveTheSameBytes) {
  const fs::path dir = freshTempDir("image_output_bands");
  const BandImage image = bandImage(23, 17, kSomePasses);
  struct Case {
    const char* name;
    OutputFormat format;
    int depth;
    bool half;
  };
  const Case cases[] = {{"a.png", OutputFormat::Png, 8, false},  {"b.png", OutputFormat::Png, 16, false},
                        {"c.exr", OutputFormat::Exr, 8, false},  {"d.exr", OutputFormat::Exr, 8, true},
                        {"e.pfm", OutputFormat::Pfm, 8, false}};
  const BandOrder orders[] = {BandOrder::OneBand, BandOrder::TopFirst, BandOrder::BottomFirst, BandOrder::Shuffled};
  for (const Case& c : cases) {
    std::vector<std::vector<std::string>> files;  // per order: the bytes of every file
    for (int o = 0; o < 4; ++o) {
      OutputSpec spec = bandSpec((dir / (std::to_string(o) + c.name)).string(), c.format, image, kSomePasses);
      spec.pngDepth = c.depth;
      spec.half = c.half;
      spec.metadata = {{"Software", "raytex"}};
      ImageWriter output(spec);
      writeBands(output, image, 5, orders[o]);
      output.finish();
      files.emplace_back();
      for (const std::string& path : output.paths()) files.back().push_back(readFile(path));
    }
    EXPECT_EQ(files[0].size(), c.format == OutputFormat::Exr ? 1u : 1u + kSomePasses.size()) << c.name;
    for (int o = 1; o < 4; ++o) EXPECT_TRUE(files[o] == files[0]) << c.name << ", order " << o;
    EXPECT_GT(files[0][0].size(), 100u) << c.name;
  }
}

TEST(ImageWriter, PfmHasItsHeaderAndItsRowsBottomUp) {
  const fs::path dir = freshTempDir("image_output_pfm");
  const std::vector<Pass> passes = {Pass::Normal, Pass::Depth, Pass::Footprint};
  const BandImage image = bandImage(9, 6, passes);
  OutputSpec spec = bandSpec((dir / "img.pfm").string(), OutputFormat::Pfm, image, passes);
  writeBandImage(spec, image, 4, BandOrder::Shuffled);
  struct File {
    std::string path, magic;
    int channels;           // in the file
    int valueChannels;      // taken from the plane
    const std::vector<float>* plane;
  };
  const File files[] = {{"img.pfm", "PF", 3, 3, &image.rgba},
                        {"img.normal.pfm", "PF", 3, 3, &image.passes[0]},
                        {"img.depth.pfm", "Pf", 1, 1, &image.passes[1]},
                        {"img.footprint.pfm", "PF", 3, 2, &image.passes[2]}};
  for (const File& f : files) {
    const std::string bytes = readFile(dir / f.path);
    const std::string header = f.magic + "\n9 6\n-1.0\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header) << f.path;
    ASSERT_EQ(bytes.size(), header.size() + size_t(9 * 6 * f.channels * 4)) << f.path;
    for (int r = 0; r < 6; ++r)  // file row r is image row 5 - r
      for (int x = 0; x < 9; ++x)
        for (int c = 0; c < f.channels; ++c) {
          const float got = littleEndianFloat(bytes, header.size() + size_t(((r * 9 + x) * f.channels + c) * 4));
          const float want = c < f.valueChannels ? (*f.plane)[size_t(((5 - r) * 9 + x) * 4 + c)] : 0.0f;
          EXPECT_EQ(bitsOf(got), bitsOf(want)) << f.path << " row " << r << " x " << x << " c " << c;
        }
  }
  EXPECT_EQ(entryCount(dir), 4u);
}

// Reads what a FIFO gets until its writer closes it, on a thread of its own.
struct FifoReader {
  int fd = -1;
  std::string bytes;
  std::thread thread;
  void start() {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    thread = std::thread([this] {
      char buffer[4096];
      for (ssize_t n; (n = read(fd, buffer, sizeof(buffer))) > 0;) bytes.append(buffer, size_t(n));
    });
  }
  std::string finish() {
    thread.join();
    close(fd);
    return bytes;
  }
};

TEST(ImageWriter, AFifoGetsTheBytesOfAFileInEitherBandOrder) {
  const fs::path dir = freshTempDir("image_output_fifo");
  const BandImage image = bandImage(31, 40, {});
  for (OutputFormat format : {OutputFormat::Png, OutputFormat::Exr, OutputFormat::Pfm}) {
    const std::string ext = format == OutputFormat::Png ? ".png" : format == OutputFormat::Exr ? ".exr" : ".pfm";
    const fs::path file = dir / ("file" + ext);
    writeBandImage(bandSpec(file.string(), format, image, {}), image, 7, BandOrder::TopFirst);
    for (BandOrder order : {BandOrder::TopFirst, BandOrder::BottomFirst}) {
      const fs::path fifo = dir / ("fifo" + ext);
      fs::remove(fifo);
      ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
      FifoReader reader;
      reader.fd = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
      ASSERT_GE(reader.fd, 0);
      {
        ImageWriter output(bandSpec(fifo.string(), format, image, {}));
        EXPECT_EQ(output.bottomUp(), format == OutputFormat::Pfm) << ext;
        reader.start();
        writeBands(output, image, 7, order);
        output.finish();
      }
      EXPECT_TRUE(reader.finish() == readFile(file)) << ext << " order " << int(order);
      EXPECT_TRUE(fs::is_fifo(fifo));
    }
  }
}

std::set<std::string> channelNames(const Imf::Header& header) {
  std::set<std::string> names;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) names.insert(it.name());
  return names;
}

// Every channel of an EXR file read as floats, width x height each.
std::map<std::string, std::vector<float>> readChannels(const std::string& path, int* width, int* height) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  *width = window.max.x + 1;
  *height = window.max.y + 1;
  std::map<std::string, std::vector<float>> planes;
  Imf::FrameBuffer frame;
  for (const std::string& name : channelNames(file.header())) {
    planes[name].resize(size_t(*width) * size_t(*height));
    frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[name].data()), sizeof(float),
                                  sizeof(float) * size_t(*width)));
  }
  file.setFrameBuffer(frame);
  file.readPixels(0, *height - 1);
  return planes;
}

TEST(ImageWriter, ExrHoldsTheFloatsThePassesAsLayersAndTheMetadata) {
  const fs::path dir = freshTempDir("image_output_exr");
  const std::vector<Pass> passes = {Pass::Normal, Pass::Depth, Pass::Footprint};
  const BandImage image = bandImage(13, 11, passes);
  OutputSpec spec = bandSpec((dir / "img.exr").string(), OutputFormat::Exr, image, passes);
  spec.metadata = {{"Software", "raytex 1"}, {"scene", "course.cfg"}};
  writeBandImage(spec, image, 3, BandOrder::TopFirst);
  Imf::InputFile file((dir / "img.exr").c_str());
  const std::set<std::string> expected = {"A",           "B",           "G",           "R",
                                          "depth.A",     "depth.Z",     "footprint.A", "footprint.X",
                                          "footprint.Y", "normal.A",    "normal.X",    "normal.Y",
                                          "normal.Z"};
  EXPECT_EQ(channelNames(file.header()), expected);
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
    EXPECT_EQ(it.channel().type, Imf::FLOAT) << it.name();
  EXPECT_EQ(file.header().lineOrder(), Imf::INCREASING_Y);
  EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
  for (const auto& [key, value] : spec.metadata) {
    const auto* attribute = file.header().findTypedAttribute<Imf::StringAttribute>(key);
    ASSERT_NE(attribute, nullptr) << key;
    EXPECT_EQ(attribute->value(), value);
  }
  int width = 0, height = 0;
  auto planes = readChannels((dir / "img.exr").string(), &width, &height);
  ASSERT_EQ(width, 13);
  ASSERT_EQ(height, 11);
  for (size_t i = 0; i < size_t(13 * 11); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(bitsOf(planes[std::string(1, "RGB"[c])][i]), bitsOf(image.rgba[i * 4 + size_t(c)]));
    EXPECT_EQ(planes["A"][i], 1.0f);
    for (size_t p = 0; p < passes.size(); ++p) {
      const PassInfo& info = passInfo(passes[p]);
      for (int c = 0; c <= info.channels; ++c) {  // the values, then the coverage
        const std::string name = std::string(info.name) + "." + (c < info.channels ? info.channelNames[c] : 'A');
        EXPECT_EQ(bitsOf(planes[name][i]), bitsOf(image.passes[p][i * 4 + size_t(c < info.channels ? c : 3)])) << name;
      }
    }
  }
}

TEST(ImageWriter, HalfExrIsWithinHalfPrecisionButPositionStaysFloat) {
  const fs::path dir = freshTempDir("image_output_half");
  const std::vector<Pass> passes = {Pass::Normal, Pass::Position};
  const BandImage image = bandImage(17, 9, passes);
  OutputSpec spec = bandSpec((dir / "img.exr").string(), OutputFormat::Exr, image, passes);
  spec.half = true;
  writeBandImage(spec, image, 4, BandOrder::TopFirst);
  Imf::InputFile file((dir / "img.exr").c_str());
  EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::HALF);
  EXPECT_EQ(file.header().channels().findChannel("normal.X")->type, Imf::HALF);
  EXPECT_EQ(file.header().channels().findChannel("position.X")->type, Imf::FLOAT);
  int width = 0, height = 0;
  auto planes = readChannels((dir / "img.exr").string(), &width, &height);
  // A half has 11 significant bits: rounding moves a value by at most 2^-11 of it (2^-25 below
  // the smallest normal half, 2^-14).
  const auto nearHalf = [](float got, float want) {
    return std::fabs(got - want) <= std::max(std::fabs(want) * 0x1p-11f, 0x1p-25f);
  };
  for (size_t i = 0; i < size_t(17 * 9); ++i) {
    for (int c = 0; c < 3; ++c) {
      const std::string rgb(1, "RGB"[c]);
      EXPECT_TRUE(nearHalf(planes[rgb][i], image.rgba[i * 4 + size_t(c)])) << rgb << " " << i;
      const std::string normal = std::string("normal.") + "XYZ"[c], position = std::string("position.") + "XYZ"[c];
      EXPECT_TRUE(nearHalf(planes[normal][i], image.passes[0][i * 4 + size_t(c)])) << normal << " " << i;
      EXPECT_EQ(bitsOf(planes[position][i]), bitsOf(image.passes[1][i * 4 + size_t(c)])) << position << " " << i;
    }
  }
  EXPECT_NE(bitsOf(planes["R"][3]), bitsOf(image.rgba[3 * 4])) << "not rounded to half: the test proves nothing";
}

TEST(ImageWriter, HalfExrClampsFiniteValuesBeyondTheHalfRangeAndCountsThem) {
  const fs::path dir = freshTempDir("image_output_half_clamp");
  const std::vector<Pass> passes = {Pass::Depth, Pass::Position};
  BandImage image = bandImage(7, 5, passes);
  // 65504 is the largest half; 65519 would round to it, 65520 and beyond to an infinity.
  const std::pair<size_t, float> over[] = {{0 * 4 + 0, 70000.0f}, {1 * 4 + 1, -1e6f}, {2 * 4 + 2, 65519.0f},
                                           {3 * 4 + 0, 3e38f}};
  for (const auto& [at, value] : over) image.rgba[at] = value;
  image.rgba[4 * 4 + 0] = 65504.0f;  // the largest half itself: written as it is, not counted
  image.rgba[5 * 4 + 1] = INFINITY;  // not finite: written as it is, as in float
  image.rgba[6 * 4 + 2] = NAN;
  image.passes[0][8 * 4] = 1e5f;     // depth: a half channel too
  image.passes[1][9 * 4] = 1e6f;     // position: float, never clamped
  OutputSpec spec = bandSpec((dir / "img.exr").string(), OutputFormat::Exr, image, passes);
  spec.half = true;
  ImageWriter output(spec);
  writeBands(output, image, 2, BandOrder::Shuffled);
  output.finish();
  EXPECT_EQ(output.clamped(), 5u);
  EXPECT_EQ(output.nonFinite(), 0u);
  int width = 0, height = 0;
  auto planes = readChannels((dir / "img.exr").string(), &width, &height);
  for (const auto& [at, value] : over)
    EXPECT_EQ(planes[std::string(1, "RGB"[at % 4])][at / 4], std::copysign(65504.0f, value)) << at;
  EXPECT_EQ(planes["R"][4], 65504.0f);
  EXPECT_EQ(planes["G"][5], INFINITY);
  EXPECT_TRUE(std::isnan(planes["B"][6]));
  EXPECT_EQ(planes["depth.Z"][8], 65504.0f);
  EXPECT_EQ(planes["position.X"][9], 1e6f);
  const auto nearHalf = [](float got, float want) {  // as in the test above
    return std::fabs(got - want) <= std::max(std::fabs(want) * 0x1p-11f, 0x1p-25f);
  };
  for (size_t i = 7; i < size_t(7 * 5); ++i)  // the pixels left as bandImage makes them
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(nearHalf(planes[std::string(1, "RGB"[c])][i], image.rgba[i * 4 + size_t(c)])) << i << " " << c;
}

TEST(ImageWriter, Png8WithoutMetadataIsTheBytesOfEncodePngAndCountsNonFiniteValues) {
  const fs::path dir = freshTempDir("image_output_png8");
  BandImage image = bandImage(21, 13, {});
  image.rgba[5 * 4 + 0] = NAN;
  image.rgba[40 * 4 + 2] = INFINITY;
  image.rgba[41 * 4 + 1] = -INFINITY;
  image.rgba[42 * 4 + 3] = NAN;  // alpha: not a colour value
  size_t expected = 0;
  for (size_t i = 0; i < image.rgba.size(); ++i) expected += i % 4 != 3 && !std::isfinite(image.rgba[i]);
  OutputSpec spec = bandSpec((dir / "img.png").string(), OutputFormat::Png, image, {});
  EXPECT_EQ(writeBandImage(spec, image, 4, BandOrder::Shuffled), expected);
  const std::vector<uint8_t> png = encodePng(encodeSrgb(image.rgba.data(), 21, 13));
  EXPECT_TRUE(readFile(dir / "img.png") == std::string(png.begin(), png.end()));
}

TEST(ImageWriter, Png16DecodesToTheSrgbValuesOfTheFloats) {
  const fs::path dir = freshTempDir("image_output_png16");
  BandImage image = bandImage(19, 7, {});
  image.rgba[3 * 4 + 1] = NAN;
  image.rgba[0] = 0.001f;  // on the curve's linear segment
  OutputSpec spec = bandSpec((dir / "img.png").string(), OutputFormat::Png, image, {});
  spec.pngDepth = 16;
  EXPECT_EQ(writeBandImage(spec, image, 3, BandOrder::BottomFirst), 1u);
  const DecodedPng png = decodePng(readFile(dir / "img.png"));
  ASSERT_TRUE(png.ok);
  EXPECT_EQ(png.width, 19);
  EXPECT_EQ(png.height, 7);
  EXPECT_EQ(png.depth, 16);
  EXPECT_EQ(png.colourType, PNG_COLOR_TYPE_RGB);
  for (size_t i = 0; i < size_t(19 * 7); ++i)
    for (size_t c = 0; c < 3; ++c) {
      const float v = image.rgba[i * 4 + c];
      const long want = std::isfinite(v) ? std::lround(srgbOracle(v) * 65535.0) : 0;
      const long got = long(png.pixels[(i * 3 + c) * 2]) << 8 | png.pixels[(i * 3 + c) * 2 + 1];  // big-endian
      EXPECT_EQ(got, want) << "pixel " << i << " channel " << c;
    }
}

TEST(ImageWriter, PngMetadataIsTextChunksAfterIhdrWithValidCrcs) {
  const fs::path dir = freshTempDir("image_output_text");
  const BandImage image = bandImage(8, 5, {Pass::Albedo});
  const Metadata metadata = {{"Software", "raytex"}, {"Comment", "a sphere\nand a plane"}, {"Title", "caf\xc3\xa9"}};
  for (int depth : {8, 16}) {
    OutputSpec spec = bandSpec((dir / ("img" + std::to_string(depth) + ".png")).string(), OutputFormat::Png, image,
                               {Pass::Albedo});
    spec.pngDepth = depth;
    spec.metadata = metadata;
    writeBandImage(spec, image, 2, BandOrder::TopFirst);
    for (const std::string& name : {"img" + std::to_string(depth) + ".png", "img" + std::to_string(depth) + ".albedo.png"}) {
      const std::string bytes = readFile(dir / name);
      const std::vector<Chunk> found = chunks(bytes);
      ASSERT_GE(found.size(), 6u) << name;
      EXPECT_EQ(found[0].type, "IHDR");
      EXPECT_EQ(found[1].type, "tEXt");
      EXPECT_EQ(found[1].data, std::string("Software\0raytex", 15));
      EXPECT_EQ(found[2].type, "tEXt");
      EXPECT_EQ(found[3].type, "iTXt");  // not ASCII: UTF-8 text
      EXPECT_EQ(found[3].data, std::string("Title\0\0\0\0\0caf\xc3\xa9", 15));
      EXPECT_EQ(found.back().type, "IEND");
      for (const Chunk& chunk : found) EXPECT_TRUE(chunk.crcOk) << name << " " << chunk.type;
      const DecodedPng png = decodePng(bytes);
      ASSERT_TRUE(png.ok) << name;
      EXPECT_EQ(png.text, metadata) << name;
    }
  }
}

TEST(ImageWriter, APassThatFitsTheUnitRangeIsAnSrgbPngBesideThePfm) {
  const fs::path dir = freshTempDir("image_output_albedo");
  const BandImage image = bandImage(6, 4, {Pass::Albedo});
  writeBandImage(bandSpec((dir / "img.pfm").string(), OutputFormat::Pfm, image, {Pass::Albedo}), image, 3,
                 BandOrder::TopFirst);
  const DecodedPng png = decodePng(readFile(dir / "img.albedo.png"));
  ASSERT_TRUE(png.ok);
  ASSERT_EQ(png.depth, 8);
  for (size_t i = 0; i < 24; ++i)
    for (size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(png.pixels[i * 3 + c], std::lround(srgbOracle(image.passes[0][i * 4 + c]) * 255.0), 1);
}

TEST(ImageWriter, DestroyedBeforeFinishItLeavesNoFileAndNoTemporary) {
  const std::vector<Pass> passes = {Pass::Normal, Pass::Albedo};
  const BandImage image = bandImage(10, 8, passes);
  for (const char* name : {"out.png", "out.exr", "out.pfm"}) {
    const fs::path dir = freshTempDir("image_output_abandon");
    writeFile(dir / name, "old");
    writeFile(dir / "out.normal.pfm", "old pass");
    const OutputFormat format = outputFormatFor((dir / name).string());
    {
      ImageWriter output(bandSpec((dir / name).string(), format, image, passes));
      output.writeBand(0, 3, image.rgba.data(), {image.passes[0].data(), image.passes[1].data()});
      EXPECT_EQ(entryCount(dir), 2u) << name;  // the files being written have no names (O_TMPFILE)
    }
    EXPECT_EQ(entryCount(dir), 2u) << name;
    EXPECT_EQ(readFile(dir / name), "old") << name;
    EXPECT_EQ(readFile(dir / "out.normal.pfm"), "old pass") << name;
  }
}

TEST(ImageWriter, RowsMissingOrWrittenTwiceAreRefusedAndNothingIsWritten) {
  const fs::path dir = freshTempDir("image_output_rows");
  const BandImage image = bandImage(5, 6, {});
  const auto kindOf = [](const std::function<void()>& step) {
    try {
      step();
    } catch (const Error& e) {
      return e.kind;
    }
    return ErrorKind::Usage;  // not thrown
  };
  for (const char* name : {"a.png", "a.exr", "a.pfm"}) {
    ImageWriter output(bandSpec((dir / name).string(), outputFormatFor(name), image, {}));
    output.writeBand(0, 2, image.rgba.data(), {});
    EXPECT_EQ(kindOf([&] { output.writeBand(1, 2, image.rgba.data(), {}); }), ErrorKind::Internal) << name;
    EXPECT_EQ(kindOf([&] { output.writeBand(5, 2, image.rgba.data(), {}); }), ErrorKind::Internal) << name;
    EXPECT_EQ(kindOf([&] { output.finish(); }), ErrorKind::Internal) << name;
  }
  EXPECT_EQ(entryCount(dir), 0u);
}

// Named temporaries (as where the file system refuses O_TMPFILE): the signal handler removes
// every one of the image's files.
TEST(ImageWriter, ASignalRemovesEveryTemporaryOfTheImage) {
  const fs::path dir = freshTempDir("image_output_signal");
  const std::vector<Pass> passes = {Pass::Normal, Pass::Depth, Pass::Albedo};
  const BandImage image = bandImage(10, 8, passes);
  pid_t child = fork();
  if (child == 0) {
    signal(SIGTERM, SIG_DFL);
    setenv("RAYTEX_TEST_NAMED_TEMP", "1", 1);
    ImageWriter output(bandSpec((dir / "out.png").string(), OutputFormat::Png, image, passes));
    _exit(entryCount(dir) == 4 && raise(SIGTERM) == 0 ? 0 : 3);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_EQ(entryCount(dir), 0u);
}

// The pass files are put in place first and the image last: when one cannot be, the files this
// output put in place are removed and the older image stays.
TEST(ImageWriter, AFailedPublishRemovesThePassesAndKeepsTheOlderImage) {
  const fs::path dir = freshTempDir("image_output_publish");
  const std::vector<Pass> passes = {Pass::Normal, Pass::Albedo};
  const BandImage image = bandImage(6, 4, passes);
  writeFile(dir / "out.png", "old");
  ImageWriter output(bandSpec((dir / "out.png").string(), OutputFormat::Png, image, passes));
  output.writeBand(0, 4, image.rgba.data(), {image.passes[0].data(), image.passes[1].data()});
  fs::create_directory(dir / "out.albedo.png");  // the second pass cannot take its name
  EXPECT_THROW(output.finish(), IoError);
  EXPECT_FALSE(fs::exists(dir / "out.normal.pfm"));
  EXPECT_EQ(readFile(dir / "out.png"), "old");
  EXPECT_EQ(entryCount(dir), 2u);
}

TEST(ImageWriter, PassFilesAreNamedAfterTheStem) {
  OutputSpec spec;
  spec.path = "dir/out.png";
  EXPECT_EQ(passFilePath(spec, Pass::Normal), "dir/out.normal.pfm");
  EXPECT_EQ(passFilePath(spec, Pass::Albedo), "dir/out.albedo.png");
  spec.path = "a.b/render.PFM";
  spec.format = OutputFormat::Pfm;
  EXPECT_EQ(passFilePath(spec, Pass::Depth), "a.b/render.depth.pfm");
  spec.format = OutputFormat::Exr;
  EXPECT_EQ(passFilePath(spec, Pass::Depth), "");
  spec.path = "-";
  spec.format = OutputFormat::Png;
  spec.width = spec.height = 4;
  spec.passes = {Pass::Depth};
  EXPECT_THROW(ImageWriter output(spec), UsageError);
}

std::string usageError(const std::function<void()>& step) {
  try {
    step();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(ImageWriter, MetadataKeysArePngKeywords) {
  const auto check = [](const Metadata& m, OutputFormat f) { return usageError([&] { checkMetadata(m, f); }); };
  EXPECT_EQ(check({{"Software", "raytex"}, {"channels", "x"}}, OutputFormat::Png), "");
  EXPECT_EQ(check({{"", "x"}}, OutputFormat::Png), "metadata key '': it must be 1 to 79 characters");
  EXPECT_NE(check({{std::string(80, 'k'), "x"}}, OutputFormat::Png), "");
  EXPECT_NE(check({{" lead", "x"}}, OutputFormat::Png), "");
  EXPECT_NE(check({{"two  spaces", "x"}}, OutputFormat::Png), "");
  EXPECT_NE(check({{"caf\xc3\xa9", "x"}}, OutputFormat::Png), "");
  EXPECT_EQ(check({{"a", "x"}, {"a", "y"}}, OutputFormat::Png), "metadata key 'a' is given twice");
  EXPECT_NE(check({{"a", std::string("x\0y", 3)}}, OutputFormat::Png), "");
  EXPECT_EQ(check({{"channels", "x"}}, OutputFormat::Exr),
            "metadata key 'channels' names an attribute every EXR file defines");
}

TEST(OutputFormat, TheExtensionNamesTheFormatInAnyCase) {
  const fs::path dir = freshTempDir("output_format");
  EXPECT_EQ(outputFormatFor("a.png"), OutputFormat::Png);
  EXPECT_EQ(outputFormatFor("d/b.EXR"), OutputFormat::Exr);
  EXPECT_EQ(outputFormatFor("c.Pfm"), OutputFormat::Pfm);
  EXPECT_EQ(outputFormatFor("-"), OutputFormat::Png);
  EXPECT_EQ(usageError([] { outputFormatFor("x.jpg"); }), "'x.jpg': unknown output format (supported: .png, .exr, .pfm)");
  EXPECT_NE(usageError([] { outputFormatFor("noextension"); }), "");
  writeFile(dir / "old.txt", "x");
  EXPECT_NE(usageError([&] { outputFormatFor((dir / "old.txt").string()); }), "");
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  ASSERT_EQ(mkfifo((dir / "fifo.exr").c_str(), 0600), 0);
  EXPECT_EQ(outputFormatFor((dir / "fifo").string()), OutputFormat::Png);
  EXPECT_EQ(outputFormatFor((dir / "fifo.exr").string()), OutputFormat::Exr);
}

TEST(AtomicFile, WritesAtOffsetsAndLeavesNothingUncommitted) {
  const fs::path dir = freshTempDir("output_file_offsets");
  writeFile(dir / "out.bin", "old");
  {
    AtomicFile file((dir / "out.bin").string());
    EXPECT_TRUE(file.seekable());
    const uint8_t head[] = {'a', 'b'}, tail[] = {'y', 'z'};
    file.writeAt(4, tail, 2);
    file.write(head, 2);
    file.writeAt(2, head, 2);
    EXPECT_EQ(entryCount(dir), 1u);  // the file being written has no name until commit (O_TMPFILE)
    EXPECT_EQ(readFile(dir / "out.bin"), "old");
    file.commit();
  }
  EXPECT_EQ(readFile(dir / "out.bin"), "ababyz");
  EXPECT_EQ(entryCount(dir), 1u);
  {
    AtomicFile file((dir / "out.bin").string());
    file.write(reinterpret_cast<const uint8_t*>("new"), 3);
  }
  EXPECT_EQ(readFile(dir / "out.bin"), "ababyz");
  EXPECT_EQ(entryCount(dir), 1u);
}

}  // namespace
