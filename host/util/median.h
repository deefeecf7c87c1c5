// The median of timings: what benchmarks and the viewer's frame statistics report, since
// machines are noisy and means follow outliers.
#pragma once

#include <algorithm>
#include <vector>

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}
