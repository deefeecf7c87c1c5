// `raytex bench`: whole headless renders timed phase by phase, medians printed as a table
// or JSON, with throughput in pixels and rays.
#pragma once

#include "cli.h"

// Exit code as renderHeadless.
int runBench(const RenderOptions& options, const BenchOptions& bench);
