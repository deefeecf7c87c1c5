// What a render writes: the output files' spec (format, depth, passes) and metadata from the
// command line's options. No Vulkan.
#pragma once

#include "cli.h"
#include "image_output.h"
#include "scene.h"

#include <string>

// The version `raytex --version` prints and the outputs' metadata carries.
constexpr const char* kRaytexVersion = "raytex 0.1.0";

// What --metadata full adds: known only once the render has run.
struct RenderFacts {
  std::string device;
  double renderMs = 0.0;  // from reading the scene to the first rows read back
};

// The metadata of a render's outputs: the version, size, samples per pixel and filter (the same
// for every render of a view, so that outputs stay byte-identical), and with --metadata full
// also the scene's path, the device and the render time from `facts`.
Metadata renderMetadata(const RenderOptions& options, const RenderJob& job, const RenderFacts& facts);

// The files a render of `job` writes to options.output: its format from the name (output_file.h,
// outputFormatFor), --depth, --half and --aov.
OutputSpec renderOutputSpec(const RenderOptions& options, const RenderJob& job, const Metadata& metadata);

// Throws UsageError when the output or a pass file beside it may not be written for this scene
// (checkOutput: one of the scene's own files, then an unknown format).
void checkRenderOutputs(const RenderOptions& options, const RenderJob& job, const Scene& scene);
