// A pure function of a float with its recent results remembered: image values repeat (an 8-bit
// file holds at most 256 values a channel, a 16-bit one 65536), and the sRGB curves, which
// `raytex diff` evaluates several times a pixel, cost a pow each. No Vulkan.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

// F(v), looked up by v's bits in a direct-mapped table of 4096 entries: a hit returns the very
// value F returned for those bits, so results are F's to the bit. Every entry starts as the
// result for one NaN's bits. One object per thread.
template <typename Result, Result (*F)(float)>
class FloatMemo {
 public:
  FloatMemo() : keys_(kSize, kStartKey), values_(kSize, F(asFloat(kStartKey))) {}
  Result operator()(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    const size_t slot = (bits * 2654435761u) >> (32 - kBits);  // Knuth's multiplicative hash
    if (keys_[slot] != bits) {
      keys_[slot] = bits;
      values_[slot] = F(v);
    }
    return values_[slot];
  }

 private:
  static constexpr int kBits = 12;
  static constexpr size_t kSize = size_t(1) << kBits;
  static constexpr uint32_t kStartKey = 0x7fc00001u;
  static float asFloat(uint32_t bits) {
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  std::vector<uint32_t> keys_;
  std::vector<Result> values_;
};
