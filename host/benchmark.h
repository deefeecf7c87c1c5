// `raytex bench`: whole headless renders timed phase by phase, medians printed as a table
// or JSON, with throughput in pixels and rays.
#pragma once

#include "cli.h"

// Throws an Error (error.h) as renderHeadless does.
void runBench(const RenderOptions& options, const BenchOptions& bench);
