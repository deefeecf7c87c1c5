#include "exr_writer.h"

#include "error.h"
#include "atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <map>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <half.h>

namespace {

// The largest finite half, 65504: a float beyond it would round to an infinity.
constexpr float kHalfMax = HALF_MAX;

// `value` as a half; a finite value beyond +-kHalfMax becomes +-kHalfMax and is counted in
// `clamped`. NaN and the infinities stay what they are.
Imath::half toHalf(float value, size_t& clamped) {
  if (std::isfinite(value) && std::fabs(value) > kHalfMax) {
    ++clamped;
    return Imath::half(std::copysign(kHalfMax, value));
  }
  return Imath::half(value);
}

// OpenEXR's output stream over an AtomicFile: in place for a regular file, else in memory until
// flush(). A failure is kept, since OpenEXR swallows those of its destructor.
class ExrStream : public Imf::OStream {
 public:
  explicit ExrStream(AtomicFile& file) : Imf::OStream(file.path().c_str()), file_(file) {}

  void write(const char c[], int n) override {
    try {
      const auto* bytes = reinterpret_cast<const uint8_t*>(c);
      if (file_.seekable()) {
        file_.writeAt(position_, bytes, size_t(n));
      } else {
        if (memory_.size() < position_ + size_t(n)) memory_.resize(position_ + size_t(n));
        memcpy(memory_.data() + position_, bytes, size_t(n));
      }
      position_ += uint64_t(n);
    } catch (...) {
      if (!failure_) failure_ = std::current_exception();
      throw;
    }
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t position) override { position_ = position; }

  // Writes the file kept in memory (an output that cannot seek); rethrows a failure.
  void flush() {
    if (failure_) std::rethrow_exception(failure_);
    if (!file_.seekable()) file_.write(memory_);
    memory_ = {};
  }

 private:
  AtomicFile& file_;
  uint64_t position_ = 0;
  std::vector<uint8_t> memory_;
  std::exception_ptr failure_;
};

// A band's planes copied, for a band that comes before its turn.
struct HeldBand {
  int rows = 0;
  std::vector<float> rgba;
  std::vector<std::vector<float>> passes;
};

// One channel of the file: where its values come from and how it stores them.
struct ExrChannel {
  std::string name;
  int source = -1;     // Band::plane: -1 the colour, i >= 0 pass i
  int component = 0;   // of the plane's vec4s; -1: the constant 1 (A)
  bool half = false;   // HALF, else FLOAT
};

// R, G, B, A, then for each pass "<name>.<letter>" per value and "<name>.A" for its coverage.
std::vector<ExrChannel> exrChannels(const OutputSpec& spec) {
  std::vector<ExrChannel> channels = {
      {"R", -1, 0, spec.half}, {"G", -1, 1, spec.half}, {"B", -1, 2, spec.half}, {"A", -1, -1, spec.half}};
  for (size_t i = 0; i < spec.passes.size(); ++i) {
    const PassInfo& info = passInfo(spec.passes[i]);
    const bool half = spec.half && !info.fullFloat;
    for (int c = 0; c < info.channels; ++c)
      channels.push_back({std::string(info.name) + "." + info.channelNames[c], int(i), c, half});
    channels.push_back({std::string(info.name) + ".A", int(i), 3, half});
  }
  return channels;
}

Imf::Header exrHeader(const OutputSpec& spec, const std::vector<ExrChannel>& channels) {
  Imf::Header header(spec.width, spec.height);  // ZIP, INCREASING_Y
  for (const ExrChannel& channel : channels)
    header.channels().insert(channel.name, Imf::Channel(channel.half ? Imf::HALF : Imf::FLOAT));
  for (const auto& [key, value] : spec.metadata) header.insert(key, Imf::StringAttribute(value));
  return header;
}

// A slice of values `size` bytes apart, `width` a row, whose first row is image row
// `firstRow`: OpenEXR addresses pixel (x, y) at base + x * xStride + y * yStride, y counted
// from the image's top.
Imf::Slice bandSlice(Imf::PixelType type, const void* first, size_t xStride, int firstRow, int width) {
  const size_t yStride = xStride * size_t(width);
  const uintptr_t base = reinterpret_cast<uintptr_t>(first) - uintptr_t(firstRow) * yStride;
  return Imf::Slice(type, reinterpret_cast<char*>(base), xStride, yStride);
}

struct ExrSink : BandSink {
  explicit ExrSink(const OutputSpec& spec)
      : spec(spec), channels(exrChannels(spec)), file(spec.path), stream(file), ones(size_t(spec.width), 1.0f),
        halfOnes(size_t(spec.width), Imath::half(1.0f)) {
    Imf::setGlobalThreadCount(0);
    guarded([&] { exr = std::make_unique<Imf::OutputFile>(stream, exrHeader(spec, channels), 0); });
  }

  // Runs an OpenEXR step; its exceptions become IoError naming the file.
  template <typename F>
  void guarded(F step) {
    try {
      step();
    } catch (const Iex::BaseExc& e) {
      throw IoError("cannot write '" + spec.path + "': " + e.what());
    }
  }

  void write(const Band& band) override {
    if (band.firstRow != nextRow) {
      hold(band);
      return;
    }
    writeInOrder(band);
    for (auto next = held.find(nextRow); next != held.end(); next = held.find(nextRow)) {
      Band early{next->first, next->second.rows, next->second.rgba.data(), {}};
      for (const auto& pass : next->second.passes) early.passes.push_back(pass.data());
      writeInOrder(early);
      held.erase(next);
    }
  }

  void hold(const Band& band) {
    const size_t floats = size_t(band.rows) * spec.width * 4;
    HeldBand copy{band.rows, std::vector<float>(band.rgba, band.rgba + floats), {}};
    for (const float* pass : band.passes) copy.passes.emplace_back(pass, pass + floats);
    held[band.firstRow] = std::move(copy);
  }

  // The slice of one channel for the band: float values straight from the band's vec4s, half
  // values converted into `halves` (OpenEXR takes half channels from half slices only), those
  // beyond the half range clamped (toHalf).
  Imf::Slice channelSlice(const ExrChannel& channel, const Band& band, Imath::half*& halves) {
    if (channel.component < 0)
      return channel.half ? Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halfOnes.data()), sizeof(Imath::half), 0)
                          : Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(ones.data()), sizeof(float), 0);
    const float* values = band.plane(channel.source) + channel.component;
    if (!channel.half) return bandSlice(Imf::FLOAT, values, 4 * sizeof(float), band.firstRow, spec.width);
    Imath::half* out = halves;
    for (size_t i = 0; i < size_t(band.rows) * spec.width; ++i) out[i] = toHalf(values[i * 4], clampedValues);
    halves += size_t(band.rows) * spec.width;
    return bandSlice(Imf::HALF, out, sizeof(Imath::half), band.firstRow, spec.width);
  }

  void writeInOrder(const Band& band) {
    const size_t halfChannels = size_t(std::count_if(channels.begin(), channels.end(),
                                                     [](const ExrChannel& c) { return c.half && c.component >= 0; }));
    halfBand.resize(halfChannels * size_t(band.rows) * spec.width);
    Imath::half* halves = halfBand.data();
    Imf::FrameBuffer frame;
    for (const ExrChannel& channel : channels) frame.insert(channel.name, channelSlice(channel, band, halves));
    guarded([&] {
      exr->setFrameBuffer(frame);
      exr->writePixels(band.rows);
    });
    nextRow += band.rows;
  }

  void complete() override {
    if (nextRow != spec.height)
      throw Error(ErrorKind::Internal, "'" + spec.path + "': rows from " + std::to_string(nextRow) + " never came");
    guarded([&] { exr.reset(); });  // writes the table of row offsets
    stream.flush();
  }

  void commit() override { file.commit(); }
  void withdraw() override { file.withdraw(); }

  size_t clamped() const override { return clampedValues; }

  OutputSpec spec;
  std::vector<ExrChannel> channels;
  AtomicFile file;
  ExrStream stream;
  std::vector<float> ones;  // A: one row, every row
  std::vector<Imath::half> halfOnes;
  std::vector<Imath::half> halfBand;     // the half channels of the band being written
  std::unique_ptr<Imf::OutputFile> exr;  // destroyed first: it writes through the stream
  int nextRow = 0;
  std::map<int, HeldBand> held;  // by first row
  size_t clampedValues = 0;      // finite values beyond the half range, written as +-kHalfMax
};

}  // namespace

std::unique_ptr<BandSink> makeExrSink(const OutputSpec& spec) { return std::make_unique<ExrSink>(spec); }
