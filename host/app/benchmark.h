// `raytex bench`: whole headless renders timed phase by phase, medians printed as a table
// or JSON, with throughput in pixels and rays.
#pragma once

#include "render_options.h"

#include <cstdint>

struct BenchOptions {
  uint32_t runs = 5;  // --runs N: whole renders, each from parse to PNG; medians reported
  bool json = false;  // --json: one JSON object instead of the table
};

// Throws an Error (error.h) as renderHeadless does.
void runBench(const RenderOptions& options, const BenchOptions& bench);
