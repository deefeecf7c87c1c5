#include "pfm_writer.h"

#include "error.h"
#include "atomic_file.h"

#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

namespace {

void putLittleEndian(uint8_t* out, float value) {
  uint32_t bits;
  memcpy(&bits, &value, 4);
  for (int i = 0; i < 4; ++i) out[i] = uint8_t(bits >> (8 * i));
}

struct PfmSink : BandSink {
  PfmSink(const std::string& path, int width, int height, int source, int channels)
      : file(path), width(width), height(height), source(source), channels(channels), nextEnd(height) {
    const std::string header = std::string(fileChannels() == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) +
                               " " + std::to_string(height) + "\n-1.0\n";
    headerBytes = header.size();
    file.write(reinterpret_cast<const uint8_t*>(header.data()), header.size());
  }

  int fileChannels() const { return channels == 1 ? 1 : 3; }
  size_t rowBytes() const { return size_t(width) * size_t(fileChannels()) * 4; }
  bool bottomUp() const override { return !file.seekable(); }

  // The band's rows as the file holds them: its last row first.
  std::vector<uint8_t> encode(const Band& band) const {
    const float* plane = band.plane(source);
    std::vector<uint8_t> bytes(size_t(band.rows) * rowBytes());
    uint8_t* out = bytes.data();
    for (int y = band.rows - 1; y >= 0; --y)
      for (size_t x = 0; x < size_t(width); ++x) {
        const float* v = plane + (size_t(y) * width + x) * 4;
        for (int c = 0; c < fileChannels(); ++c, out += 4) putLittleEndian(out, c < channels ? v[c] : 0.0f);
      }
    return bytes;
  }

  void write(const Band& band) override {
    std::vector<uint8_t> bytes = encode(band);
    if (file.seekable()) {
      file.writeAt(headerBytes + size_t(height - band.firstRow - band.rows) * rowBytes(), bytes.data(), bytes.size());
      return;
    }
    held[band.firstRow + band.rows] = {band.firstRow, std::move(bytes)};
    // Appends every held band that ends where the rows written so far begin.
    for (auto next = held.find(nextEnd); next != held.end(); next = held.find(nextEnd)) {
      file.write(next->second.second);
      nextEnd = next->second.first;
      held.erase(next);
    }
  }

  void complete() override {
    if (!file.seekable() && nextEnd != 0)
      throw Error(ErrorKind::Internal, "'" + file.path() + "': rows 0 to " + std::to_string(nextEnd - 1) + " never came");
  }

  void commit() override { file.commit(); }
  void withdraw() override { file.withdraw(); }

  AtomicFile file;
  int width, height, source, channels;
  size_t headerBytes = 0;
  int nextEnd;  // cannot seek: the rows from here down are written
  std::map<int, std::pair<int, std::vector<uint8_t>>> held;  // by end row: first row, bytes
};

}  // namespace

std::unique_ptr<BandSink> makePfmSink(const std::string& path, int width, int height, int source, int channels) {
  return std::make_unique<PfmSink>(path, width, height, source, channels);
}
