#include "render_command.h"

#include "error.h"
#include "headless.h"
#include "atomic_file.h"
#include "parser.h"
#include "reference_render.h"
#include "render_files.h"
#include "scene_notes.h"

#include <chrono>
#include <cstdio>

#include <sys/stat.h>
#include <unistd.h>

namespace {

using Clock = std::chrono::steady_clock;

// The float64 CPU reference: no Vulkan at all.
void runReference(const RenderOptions& options) {
  Clock::time_point start = Clock::now(), t = start;
  Scene scene = parseSceneFile(options.scene, readPolicyOf(options));
  printSceneNotes(scene, stderr);
  const RenderJob job = resolveJob(options, scene.render, 1);
  checkRenderOutputs(options, job, scene);
  const double parseMs = lapMs(t);
  ReferenceImage reference = renderReference(scene, int(job.width), int(job.height), int(job.samplesPerSide), 0,
                                             options.maxImageMiB);
  const double renderMs = lapMs(t);
  std::vector<float> rgba = referenceToRgba(reference);
  const RenderFacts facts{"float64 CPU reference", std::chrono::duration<double, std::milli>(Clock::now() - start).count()};
  ImageWriter output(renderOutputSpec(options, job, renderMetadata(options, job, facts)));
  output.writeBand(0, int(job.height), rgba.data(), {});
  output.finish();
  printOutputWarnings(output, stderr);
  const double encodeMs = lapMs(t);
  if (options.stats)
    printf("parse %.1f ms | reference %.1f ms | encode %.1f ms | %ux%u, %u spp\n", parseMs, renderMs, encodeMs,
           job.width, job.height, job.samplesPerPixel);
}

// Several scenes (or -o DIR/): one device, one image each; the first failure's kind is the
// process's, behind a summary line.
void runBatch(const RenderOptions& options) {
  const std::string extension = "." + options.format;
  const BatchResult result = renderBatch(options, planBatch(options.scenes, options.output, extension));
  if (result.failed > 0)
    throw Error(result.firstFailure, std::to_string(result.failed) + " of " + std::to_string(options.scenes.size()) +
                                         " scenes failed");
}

// render --compare: the render's options with the reference and the heat map in its output
// plan, checked before anything renders. The output is read back, so it is a regular file.
RenderOptions withComparison(const RenderOptions& given, const DiffOptions& diff) {
  RenderOptions options = given;
  struct stat st;
  if (stat(options.output.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
    throw UsageError("--compare reads the output back: '" + options.output + "' is not a regular file");
  options.alongside = comparePlan(diff);
  return options;
}

// render --compare: the output file against the reference, as raytex diff reports it; a limit
// exceeded is exit 3 (render's own failures keep 1 and 2).
int compareOutput(const RenderOptions& options, DiffOptions diff) {
  diff.test = options.output;
  return runDiff(diff) == 0 ? 0 : 3;
}

void runRender(const RenderOptions& options) {
  if (isOutputDirectory(options.output)) return runBatch(options);
  if (options.output == "-" && isatty(fileno(stdout)))
    throw UsageError("-o - writes the PNG to standard output, which is a terminal");
  if (options.reference) return runReference(options);
  HeadlessRender render;
  renderHeadless(options, 0, &render);
  const PhaseTimes& t = render.times;
  if (!options.stats) return;
  printf("device %.1f ms | parse %.1f ms | upload %.1f ms | pipeline %.1f ms | render %.1f ms | "
         "readback %.1f ms | encode %.1f ms | images %.1f MiB | %ux%u, %u spp",
         t.device, t.parse, t.upload, t.pipeline, t.firstDispatch, t.readback, t.encode,
         double(render.imageBytes) / (1024.0 * 1024.0), render.job.width, render.job.height,
         render.job.samplesPerPixel);
  if (render.job.filter == TextureFilter::Coverage)
    printf(" | %llu edge %s", static_cast<unsigned long long>(render.edgeSamples),
           render.job.samplesPerPixel == 1 ? "pixels" : "samples");
  printf("\n");
}

}  // namespace

int runRenderCommand(const RenderOptions& options, const DiffOptions& compare) {
  if (compare.reference.empty()) {
    runRender(options);
    return 0;
  }
  runRender(withComparison(options, compare));
  return compareOutput(options, compare);
}
