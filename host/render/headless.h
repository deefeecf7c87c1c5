// One headless render, phase by phase: what `raytex render` runs and `raytex bench` times.
#pragma once

#include "batch.h"
#include "render_options.h"
#include "error.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

// Milliseconds since `start`, which it resets to now: one call per phase.
double lapMs(std::chrono::steady_clock::time_point& start);

// Wall-clock milliseconds of each phase, in the order they run.
struct PhaseTimes {
  double parse = 0;          // scene file, images, GPU structs (before any Vulkan)
  double device = 0;         // instance and device creation, resources
  double upload = 0;         // scene buffers and image textures
  double pipeline = 0;       // the kernel specialised to the scene (vkCreateComputePipelines)
  double firstDispatch = 0;  // the first frame, wall clock: lavapipe compiles at the first dispatch
  double readback = 0;       // image to host and sRGB 8-bit
  double encode = 0;         // PNG encode, and the file write when there is an output
  double endToEnd() const { return parse + device + upload + pipeline + firstDispatch + readback + encode; }
};

struct HeadlessRender {
  RenderJob job;
  PhaseTimes times;
  std::vector<double> frameMs;  // GPU time (timestamps) of the frames after the first
  std::string deviceName;
  size_t nonFinite = 0;  // colour values written as black
  uint64_t imageBytes = 0;  // GPU memory of the image textures: the sum of their chains
  uint64_t edgeSamples = 0;  // samples the coverage filter's edge pass shaded again (pixels at 1 spp)
};

// Renders options.scene on Vulkan, then `extraFrames` more frames of the same image (timed),
// and writes its output files (render_files.h; bench without -o: a PNG encoded and dropped, for
// the encode phase). Throws an Error (error.h) on failure,
// with nothing written. `steady`: tile kernels wherever they save time per frame, not only
// where they pay for their pipelines in this render.
void renderHeadless(const RenderOptions& options, uint32_t extraFrames, HeadlessRender* out, bool steady = false);

struct BatchResult {
  size_t failed = 0;  // scenes that failed, each reported on stderr as it failed
  ErrorKind firstFailure = ErrorKind::Internal;  // the kind of the first that failed
};

// Renders each item's scene on one device, one after another, writing its output as render
// does (a scene's failure is reported on stderr and the next one renders). Throws an Error when
// the device cannot be created.
BatchResult renderBatch(const RenderOptions& options, const std::vector<BatchItem>& items);
