// Numbers for test messages and recorded test properties.
#pragma once

#include <cstdio>
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
