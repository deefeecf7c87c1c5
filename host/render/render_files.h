// What a render writes: the output files' spec (format, depth, passes) and metadata from the
// command line's options. No Vulkan.
#pragma once

#include "render_options.h"
#include "image_writer.h"
#include "output_plan.h"
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

// The files a render of `job` writes to options.output: its format from the name (atomic_file.h,
// outputFormatFor), --depth, --half and --aov.
OutputSpec renderOutputSpec(const RenderOptions& options, const RenderJob& job, const Metadata& metadata);

// The output plan of one render (output_plan.h): the image -o names and every pass file beside
// it, the scene's files and images, and options.alongside (render --compare's reference and heat
// map). In a `batch` the messages name the scene ("the image of 'a.cfg'"), and the images are not
// named on the command line: one that exists as a device or FIFO is refused. An output of no
// known format is planned without pass files (its refusal is checkRenderOutputs').
OutputPlan planRender(const RenderOptions& options, const RenderJob& job, const Scene& scene, bool batch);

// Checks the plan of one render (checkPlan(planRender(...))), then the output's format
// (outputFormatFor), before any work: throws UsageError or IoError, and nothing is written.
void checkRenderOutputs(const RenderOptions& options, const RenderJob& job, const Scene& scene);
