// Numbers for test messages and recorded test properties, and the bits of a float.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

// `v` with four decimals ("0.1234"): errors and RMSEs of images.
inline std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

// `v` to three significant digits ("1e+06", "0.000123"): quantities over many decades.
inline std::string fmtG(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// The bits of `v`, for comparing floats exactly (NaNs and signed zeros included).
inline uint32_t bitsOf(float v) {
  uint32_t bits;
  std::memcpy(&bits, &v, 4);
  return bits;
}
