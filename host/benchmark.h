// `raytex bench`: whole headless renders timed phase by phase, medians printed as a table
// or JSON, with throughput in pixels and rays.
#pragma once

#include "cli.h"
#include "scene.h"

#include <cstdint>

struct RayCount {
  uint64_t primary = 0;
  uint64_t shadow = 0;
};

// The rays one frame traces: width x height x spp primary rays, and one shadow ray per
// primary hit and light in front of the surface (the kernel's shade()). Shadow rays are
// counted from pixel-centre hits on the CPU (float64) and scaled by spp: exact at 1 spp.
RayCount countRays(const Scene& scene, uint32_t width, uint32_t height, uint32_t samplesPerPixel);

// Exit code as renderHeadless.
int runBench(const RenderOptions& options, const BenchOptions& bench);
