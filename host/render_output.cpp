#include "render_output.h"

#include <cstdio>

Metadata renderMetadata(const RenderOptions& options, const RenderJob& job, const RenderFacts& facts) {
  Metadata m = {
      {"Software", kRaytexVersion},
      {"Image size", std::to_string(job.width) + "x" + std::to_string(job.height)},
      {"Samples per pixel", std::to_string(job.samplesPerPixel)},
      {"Texture filter", textureFilterName(job.filter)},
  };
  if (job.imageFilter != ImageFilter::Anisotropic) m.push_back({"Image filter", imageFilterName(job.imageFilter)});
  if (!options.fullMetadata) return m;
  char ms[32];
  snprintf(ms, sizeof ms, "%.1f ms", facts.renderMs);
  m.push_back({"Scene", options.scene});
  m.push_back({"Source", facts.device});  // PNG's keyword for the device that made the image
  m.push_back({"Render time", ms});
  return m;
}

OutputSpec renderOutputSpec(const RenderOptions& options, const RenderJob& job, const Metadata& metadata) {
  OutputSpec spec;
  spec.path = options.output;
  spec.format = outputFormatFor(options.output);
  spec.width = int(job.width);
  spec.height = int(job.height);
  spec.pngDepth = int(options.pngDepth);
  spec.half = options.half;
  spec.passes = options.passes;
  spec.metadata = metadata;
  return spec;
}

void checkRenderOutputs(const RenderOptions& options, const RenderJob& job, const Scene& scene) {
  checkOutput(options.output, scene);
  const OutputSpec spec = renderOutputSpec(options, job, {});
  for (Pass pass : spec.passes) {
    const std::string path = passFilePath(spec, pass);
    if (!path.empty()) checkOutput(path, scene);
  }
}
