#include "render_files.h"

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

namespace {

bool knownFormat(const std::string& path) {
  try {
    outputFormatFor(path);
    return true;
  } catch (const UsageError&) {
    return false;
  }
}

}  // namespace

OutputPlan planRender(const RenderOptions& options, const RenderJob& job, const Scene& scene, bool batch) {
  OutputPlan plan;
  const std::string of = batch ? " of '" + scene.path + "'" : "";
  if (!options.output.empty()) plan.writes.push_back({options.output, "the image" + of, !batch, ""});
  // An unknown extension has no pass files; it is refused after the plan's check (checkRenderOutputs).
  if (!options.output.empty() && knownFormat(options.output)) {
    const OutputSpec spec = renderOutputSpec(options, job, {});
    for (Pass pass : spec.passes) {
      const std::string path = passFilePath(spec, pass);
      if (!path.empty())
        plan.writes.push_back({path, "the " + std::string(passInfo(pass).name) + " pass" + of, false, options.output});
    }
  }
  planSceneReads(plan, scene, batch ? "the scene '" + scene.path + "'" : "the scene");
  mergePlan(plan, options.alongside);
  return plan;
}

void checkRenderOutputs(const RenderOptions& options, const RenderJob& job, const Scene& scene) {
  checkPlan(planRender(options, job, scene, false));
  if (!options.output.empty()) outputFormatFor(options.output);  // an unknown extension
}
