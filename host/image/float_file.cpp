#include "float_file.h"

#include "error.h"
#include "input_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>
#include <ImfThreading.h>

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& message) {
  throw ImageInputError(path + ": " + message);
}

std::string sizeText(int64_t width, int64_t height) { return std::to_string(width) + "x" + std::to_string(height); }

// A regular file open for reading, closed on destruction.
struct InputFd {
  int fd = -1;
  uint64_t size = 0;
  ~InputFd() {
    if (fd >= 0) close(fd);
  }
};

// Opens `path`: a regular file only (input_file.h).
void openRegular(const std::string& path, InputFd& in) {
  std::string why;
  in.fd = openRegularFile(path, &why);
  if (in.fd < 0) refuse(path, why == "not a regular file" ? why : "cannot open: " + why);
  struct stat st {};
  fstat(in.fd, &st);
  in.size = uint64_t(st.st_size);
}

// Reads `size` bytes at `offset`; false when the file ends first or a read fails.
bool readAt(int fd, uint64_t offset, void* out, size_t size) {
  auto* bytes = static_cast<uint8_t*>(out);
  while (size > 0) {
    ssize_t n = pread(fd, bytes, size, off_t(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    offset += uint64_t(n);
    size -= size_t(n);
  }
  return true;
}

void checkSize(const std::string& path, int64_t width, int64_t height, uint64_t maxBytes) {
  if (width <= 0 || height <= 0) refuse(path, "its header gives a size of " + sizeText(width, height));
  if (width > kMaxImageFileSide || height > kMaxImageFileSide)
    refuse(path, sizeText(width, height) + " is over the limit of " + std::to_string(kMaxImageFileSide) +
                     " pixels a side");
  const uint64_t bytes = uint64_t(width) * uint64_t(height) * 12;
  if (bytes > maxBytes)
    refuse(path, sizeText(width, height) + " needs " + std::to_string(bytes) +
                     " bytes as float RGB, over the limit of " + std::to_string(maxBytes));
}

// --- PFM ---

struct PfmHeader {
  int channels = 3;
  int64_t width = 0, height = 0;
  bool littleEndian = true;
  size_t bytes = 0;  // where the pixels start
};

// A decimal count of the header; a very long one reads as over any limit.
int64_t pfmCount(const std::string& path, const std::string& token) {
  if (token.empty() || !std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }))
    refuse(path, "the PFM header is malformed: '" + token + "' is not a size");
  return token.size() > 9 ? int64_t(1) << 40 : std::stoll(token);
}

// "PF" or "Pf", width, height and scale, separated by whitespace; the pixels start after the
// one whitespace byte that follows the scale.
PfmHeader parsePfmHeader(const std::string& path, const uint8_t* b, size_t n) {
  if (n < 2 || b[0] != 'P' || (b[1] != 'F' && b[1] != 'f'))
    refuse(path, n == 0 ? "not a PFM file (the file is empty)" : "not a PFM file (it starts with neither PF nor Pf)");
  const auto space = [&](size_t i) { return i < n && std::isspace(b[i]); };
  size_t at = 2;
  std::string tokens[3];
  for (std::string& token : tokens) {
    if (!space(at)) refuse(path, "the PFM header is malformed or cut short");
    while (space(at)) ++at;
    while (at < n && !space(at) && token.size() < 32) token += char(b[at++]);
  }
  if (!space(at)) refuse(path, "the PFM header is malformed or cut short");
  PfmHeader header;
  header.channels = b[1] == 'F' ? 3 : 1;
  header.width = pfmCount(path, tokens[0]);
  header.height = pfmCount(path, tokens[1]);
  char* end = nullptr;
  const double scale = strtod(tokens[2].c_str(), &end);
  if (*end != '\0' || !std::isfinite(scale) || scale == 0.0)
    refuse(path, "the PFM header is malformed: '" + tokens[2] + "' is not a scale");
  header.littleEndian = scale < 0.0;
  header.bytes = at + 1;
  return header;
}

float pfmValue(const uint8_t* b, bool littleEndian) {
  uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits |= uint32_t(b[littleEndian ? i : 3 - i]) << (8 * i);
  float v;
  memcpy(&v, &bits, 4);
  return v;
}

// --- EXR ---

// What the EXR header says, read before OpenEXR allocates anything for it.
struct ExrLayout {
  bool hasDataWindow = false;
  int64_t xMin = 0, yMin = 0, xMax = -1, yMax = -1;
  int compression = -1;
  bool tiled = false;
  uint32_t tileWidth = 0, tileHeight = 0;
  uint64_t bytesPerPixel = 0;  // every channel
  uint64_t headerEnd = 0;
};

// Little-endian values read through the file, never past its end.
struct ExrCursor {
  const std::string& path;
  const InputFd& in;
  uint64_t at = 0;

  void read(void* out, size_t n) {
    if (n > in.size - std::min(at, in.size) || !readAt(in.fd, at, out, n))
      refuse(path, "the EXR header is cut short or corrupt");
    at += n;
  }
  uint32_t u32() {
    uint8_t b[4];
    read(b, 4);
    return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
  }
  int64_t i32() { return int64_t(int32_t(u32())); }
  std::string name(size_t maxLength) {
    std::string s;
    for (char c = 1;;) {
      read(&c, 1);
      if (c == '\0') return s;
      if (s.size() == maxLength) refuse(path, "the EXR header is corrupt (a name is too long)");
      s += c;
    }
  }
};

// The bytes a pixel of every channel of a channel list takes.
uint64_t channelBytes(ExrCursor& cursor, size_t maxName) {
  uint64_t bytes = 0;
  while (!cursor.name(maxName).empty()) {
    const uint32_t type = cursor.u32();
    uint8_t skipped[12];  // linear flag, reserved, x and y sampling
    cursor.read(skipped, sizeof(skipped));
    if (type > 2) refuse(cursor.path, "the EXR header is corrupt (a channel of type " + std::to_string(type) + ")");
    bytes += type == 1 ? 2 : 4;  // HALF, else UINT or FLOAT
  }
  return bytes;
}

// Reads one attribute's value into `layout` when it is one the checks use (of its usual type;
// OpenEXR refuses any other).
void readExrAttribute(ExrCursor& cursor, const std::string& name, const std::string& type, size_t maxName,
                      ExrLayout& layout) {
  if (name == "dataWindow" && type == "box2i") {
    layout.hasDataWindow = true;
    layout.xMin = cursor.i32();
    layout.yMin = cursor.i32();
    layout.xMax = cursor.i32();
    layout.yMax = cursor.i32();
  } else if (name == "compression" && type == "compression") {
    uint8_t c = 0;
    cursor.read(&c, 1);
    layout.compression = c;
  } else if (name == "tiles" && type == "tiledesc") {
    layout.tileWidth = cursor.u32();
    layout.tileHeight = cursor.u32();
  } else if (name == "channels" && type == "chlist") {
    layout.bytesPerPixel = channelBytes(cursor, maxName);
  }
}

// The magic number, the version and the header's attributes.
ExrLayout readExrLayout(const std::string& path, const InputFd& in) {
  uint8_t magic[4] = {};
  if (in.size < 8 || !readAt(in.fd, 0, magic, 4) || memcmp(magic, "\x76\x2f\x31\x01", 4) != 0)
    refuse(path, in.size == 0 ? "not an EXR file (the file is empty)" : "not an EXR file (no EXR magic number)");
  ExrCursor cursor{path, in, 4};
  const uint32_t version = cursor.u32();
  if ((version & 0xff) != 2) refuse(path, "EXR version " + std::to_string(version & 0xff) + " is not supported");
  if (version & 0x800) refuse(path, "deep EXR data is not supported");
  if (version & 0x1000) refuse(path, "multi-part EXR files are not supported");
  ExrLayout layout;
  layout.tiled = version & 0x200;
  const size_t maxName = version & 0x400 ? 255 : 31;
  for (std::string name = cursor.name(maxName); !name.empty(); name = cursor.name(maxName)) {
    const std::string type = cursor.name(maxName);
    const uint32_t size = cursor.u32();
    const uint64_t valueAt = cursor.at;
    if (size > in.size - std::min(valueAt, in.size)) refuse(path, "the EXR header is cut short or corrupt");
    readExrAttribute(cursor, name, type, maxName, layout);
    cursor.at = valueAt + size;
  }
  layout.headerEnd = cursor.at;
  return layout;
}

// Rows in each chunk of a scanline file for its compression (OpenEXR's table); 256, the most,
// for one it does not know (OpenEXR refuses it later).
uint64_t linesPerChunk(int compression) {
  static const int lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression >= 0 && compression < 10 ? uint64_t(lines[compression]) : 256;
}

// The size, and what OpenEXR allocates from the header before reading pixels: the table of
// chunk offsets (which the file must hold) and one chunk of every channel.
void checkExrLayout(const std::string& path, const ExrLayout& layout, uint64_t fileSize, uint64_t maxBytes) {
  if (!layout.hasDataWindow) refuse(path, "the EXR header has no data window");
  const int64_t width = layout.xMax - layout.xMin + 1, height = layout.yMax - layout.yMin + 1;
  checkSize(path, width, height, maxBytes);
  if (layout.tiled && (layout.tileWidth < 1 || layout.tileHeight < 1 || layout.tileWidth > uint32_t(kMaxImageFileSide) ||
                       layout.tileHeight > uint32_t(kMaxImageFileSide)))
    refuse(path, "the EXR header gives tiles of " + sizeText(layout.tileWidth, layout.tileHeight));
  const uint64_t chunkWidth = layout.tiled ? layout.tileWidth : uint64_t(width);
  const uint64_t chunkHeight = layout.tiled ? layout.tileHeight : linesPerChunk(layout.compression);
  const uint64_t chunks = (uint64_t(width) + chunkWidth - 1) / chunkWidth * ((uint64_t(height) + chunkHeight - 1) / chunkHeight);
  if (chunks * 8 > fileSize - layout.headerEnd) refuse(path, "the file ends early (in its table of offsets)");
  const uint64_t chunkBytes = chunkWidth * chunkHeight * layout.bytesPerPixel;
  if (chunkBytes > maxBytes)
    refuse(path, "its channels need " + std::to_string(chunkBytes) + " bytes a chunk, over the limit of " +
                     std::to_string(maxBytes));
}

// OpenEXR's input stream over the open file.
class ExrInput : public Imf::IStream {
 public:
  ExrInput(const std::string& path, const InputFd& in) : Imf::IStream(path.c_str()), in_(in) {}
  bool read(char c[], int n) override {
    if (n < 0 || uint64_t(n) > in_.size - std::min(position_, in_.size) || !readAt(in_.fd, position_, c, size_t(n)))
      throw Iex::InputExc("the file ends early");
    position_ += uint64_t(n);
    return true;
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override { position_ = position; }

 private:
  const InputFd& in_;
  uint64_t position_ = 0;
};

// Where an EXR file's colour is: its R, G and B channels; else Y with chroma RY and BY, as
// OpenEXR's RgbaOutputFile writes luminance and chroma; else Y alone, grey.
enum class ExrColour { Rgb, LuminanceChroma, Luminance };

// Refuses a channel that is not sampled `sampling` x `sampling`.
void checkSampling(const std::string& path, const Imf::ChannelList& channels, const char* name, int sampling) {
  const Imf::Channel* channel = channels.findChannel(name);
  if (channel->xSampling != sampling || channel->ySampling != sampling)
    refuse(path, std::string("the EXR channel ") + name + " is sampled " + std::to_string(channel->xSampling) + "x" +
                     std::to_string(channel->ySampling) + ", which is not supported here (only " +
                     std::to_string(sampling) + "x" + std::to_string(sampling) + ")");
}

// The colour channels of the file's first layer (the unnamed one): R, G and B when it has all
// three, whatever else it holds; chroma only beside Y, both RY and BY, each sampled 2x2.
ExrColour exrColour(const std::string& path, const Imf::ChannelList& channels) {
  if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B")) {
    for (const char* name : {"R", "G", "B"}) checkSampling(path, channels, name, 1);
    return ExrColour::Rgb;
  }
  if (!channels.findChannel("Y")) refuse(path, "the EXR file has no R, G and B channels, nor Y");
  checkSampling(path, channels, "Y", 1);
  const bool ry = channels.findChannel("RY"), by = channels.findChannel("BY");
  if (!ry && !by) return ExrColour::Luminance;
  if (!ry || !by) refuse(path, "the EXR file has luminance Y and one chroma channel of RY and BY, not both");
  for (const char* name : {"RY", "BY"}) checkSampling(path, channels, name, 2);
  return ExrColour::LuminanceChroma;
}

// R, G and B, or Y into every channel, as stored (float), through one frame buffer.
void readChannels(Imf::InputFile& file, ExrColour colour, FloatImage& image) {
  const Imath::Box2i window = file.header().dataWindow();
  const std::vector<std::string> names = colour == ExrColour::Rgb ? std::vector<std::string>{"R", "G", "B"}
                                                                   : std::vector<std::string>{"Y"};
  const size_t xStride = 3 * sizeof(float), yStride = xStride * size_t(image.width);
  // OpenEXR addresses pixel (x, y) of the data window at base + x * xStride + y * yStride.
  const uintptr_t origin = reinterpret_cast<uintptr_t>(image.pixels.data()) - uintptr_t(intptr_t(window.min.y)) * yStride -
                           uintptr_t(intptr_t(window.min.x)) * xStride;
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < names.size(); ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(origin + c * sizeof(float)), xStride, yStride));
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  if (names.size() == 1)
    for (size_t i = 0; i < image.pixels.size(); i += 3) image.pixels[i + 1] = image.pixels[i + 2] = image.pixels[i];
}

// Luminance and chroma converted to RGB by OpenEXR's RgbaInputFile (the chroma filtered back
// to every pixel, the primaries of the file's chromaticities, else Rec. 709): half values, read
// a row at a time into one row of Imf::Rgba, so that only a row is held beside the image.
void readLuminanceChroma(const std::string& path, const InputFd& in, FloatImage& image) {
  ExrInput stream(path, in);
  Imf::RgbaInputFile file(stream, 0);
  const Imath::Box2i window = file.dataWindow();
  std::vector<Imf::Rgba> row(size_t(image.width));
  // Pixel (x, y) at base + x + y * 0: every row into `row`.
  const uintptr_t base = reinterpret_cast<uintptr_t>(row.data()) - uintptr_t(intptr_t(window.min.x)) * sizeof(Imf::Rgba);
  file.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(base), 1, 0);
  for (int y = window.min.y; y <= window.max.y; ++y) {
    file.readPixels(y);
    float* out = image.pixels.data() + size_t(y - window.min.y) * size_t(image.width) * 3;
    for (const Imf::Rgba& pixel : row) {
      *out++ = float(pixel.r);
      *out++ = float(pixel.g);
      *out++ = float(pixel.b);
    }
  }
}

FloatImage decodeExr(const std::string& path, const InputFd& in) {
  Imf::setGlobalThreadCount(0);
  ExrInput stream(path, in);
  Imf::InputFile file(stream, 0);
  const ExrColour colour = exrColour(path, file.header().channels());
  if (!file.isComplete()) refuse(path, "the file ends early or its table of offsets is corrupt");
  const Imath::Box2i window = file.header().dataWindow();
  FloatImage image;
  image.width = window.max.x - window.min.x + 1;
  image.height = window.max.y - window.min.y + 1;
  image.channels = 3;
  image.pixels.assign(size_t(image.width) * size_t(image.height) * 3, 0.0f);
  if (colour == ExrColour::LuminanceChroma)
    readLuminanceChroma(path, in, image);
  else
    readChannels(file, colour, image);
  return image;
}

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

}  // namespace

FloatImage readExr(const std::string& path, uint64_t maxBytes) {
  InputFd in;
  openRegular(path, in);
  checkExrLayout(path, readExrLayout(path, in), in.size, maxBytes);
  try {
    return decodeExr(path, in);
  } catch (const ImageInputError&) {
    throw;
  } catch (const std::bad_alloc&) {
    refuse(path, "out of memory while decoding");
  } catch (const std::exception& e) {
    refuse(path, oneLine(e.what()));
  }
}

FloatImage readPfm(const std::string& path, uint64_t maxBytes) {
  InputFd in;
  openRegular(path, in);
  uint8_t head[256];
  const size_t n = size_t(std::min<uint64_t>(in.size, sizeof(head)));
  if (!readAt(in.fd, 0, head, n)) refuse(path, "cannot read its bytes (did it change while it was read?)");
  const PfmHeader header = parsePfmHeader(path, head, n);
  checkSize(path, header.width, header.height, maxBytes);
  const size_t width = size_t(header.width), height = size_t(header.height), channels = size_t(header.channels);
  const uint64_t pixelBytes = uint64_t(width) * height * channels * 4;
  if (in.size != header.bytes + pixelBytes)
    refuse(path, "the pixels of a " + sizeText(header.width, header.height) + (channels == 1 ? " Pf" : " PF") +
                     " take " + std::to_string(pixelBytes) + " bytes, the file holds " +
                     std::to_string(in.size - std::min<uint64_t>(in.size, header.bytes)) + " bytes" +
                     (in.size < header.bytes + pixelBytes ? " (it ends early)" : ""));
  FloatImage image{int(width), int(height), 3, std::vector<float>(width * height * 3)};
  std::vector<uint8_t> row(width * channels * 4);
  for (size_t r = 0; r < height; ++r) {
    if (!readAt(in.fd, header.bytes + r * row.size(), row.data(), row.size()))
      refuse(path, "cannot read its bytes (did it change while it was read?)");
    float* out = image.pixels.data() + (height - 1 - r) * width * 3;  // rows are stored bottom up
    for (size_t x = 0; x < width; ++x)
      for (size_t c = 0; c < 3; ++c)
        out[x * 3 + c] = pfmValue(row.data() + (x * channels + (channels == 1 ? 0 : c)) * 4, header.littleEndian);
  }
  return image;
}
