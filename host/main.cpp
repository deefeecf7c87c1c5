// raytex: texture-mapping ray tracer on Vulkan compute. Subcommands in cli.cpp's usage.
#include "cli.h"
#include "benchmark.h"
#include "device.h"
#include "exit_status.h"
#include "headless.h"
#include "image_io.h"
#include "output_file.h"
#include "parser.h"
#include "reference_render.h"
#include "viewer.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace {

using Clock = std::chrono::steady_clock;

// The float64 CPU reference: no Vulkan at all.
int runReference(const RenderOptions& options, const RenderJob& job, const Scene& scene, Clock::time_point t,
                 double parseMs) {
  ReferenceImage reference;
  try {
    reference = renderReference(scene, int(job.width), int(job.height), int(job.samplesPerSide), 0,
                                options.maxImageMiB);
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  double renderMs = lapMs(t);
  std::vector<float> rgba = referenceToRgba(reference);
  size_t nonFinite = 0;
  ImageRGBA8 image = encodeSrgb(rgba.data(), int(job.width), int(job.height), &nonFinite);
  if (int rc = savePng(options.output, image, nonFinite)) return rc;
  double encodeMs = lapMs(t);
  if (options.stats)
    printf("parse %.1f ms | reference %.1f ms | encode %.1f ms | %ux%u, %u spp\n", parseMs, renderMs,
           encodeMs, job.width, job.height, job.samplesPerPixel);
  return 0;
}

int runRender(const RenderOptions& options) {
  if (!options.reference) {
    HeadlessRender render;
    int rc = renderHeadless(options, 0, &render);
    const PhaseTimes& t = render.times;
    if (rc == 0 && options.stats)
      printf("device %.1f ms | parse %.1f ms | upload %.1f ms | pipeline %.1f ms | render %.1f ms | "
             "readback %.1f ms | encode %.1f ms | images %.1f MiB | %ux%u, %u spp\n",
             t.device, t.parse, t.upload, t.pipeline, t.firstDispatch, t.readback, t.encode,
             double(render.imageBytes) / (1024.0 * 1024.0), render.job.width, render.job.height,
             render.job.samplesPerPixel);
    return rc;
  }
  Clock::time_point t = Clock::now();
  Scene scene;
  RenderJob job;
  try {
    scene = parseSceneFile(options.scene, ReadPolicy{options.allowRead});
    std::string error;
    if (!resolveJob(options, scene.render, 1, &job, &error)) {
      fprintf(stderr, "raytex: %s\n", error.c_str());
      return 2;
    }
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (std::string clash = outputClash(options.output, scene); !clash.empty()) {
    fprintf(stderr, "raytex: %s\n", clash.c_str());
    return 2;
  }
  return runReference(options, job, scene, t, lapMs(t));
}

int runCommand(const CliArgs& cli) {
  switch (cli.command) {
    case CliCommand::Help:
      fputs(usageText().c_str(), stdout);
      return 0;
    case CliCommand::Version:
      puts("raytex 0.1.0");
      return 0;
    case CliCommand::Devices:
      fputs(listDevices().c_str(), stdout);
      return 0;
    case CliCommand::Render:
      return runRender(cli.render);
    case CliCommand::View:
      return runViewer(cli.render);
    case CliCommand::Bench:
      return runBench(cli.render, cli.bench);
  }
  return 1;
}

}  // namespace

// Every command ends here: an escaping exception is one line and exit 1, and so is output
// that could not be written to stdout.
int main(int argc, char** argv) {
  // Output to a file or pipe is held until checkedExit (up to 64 KiB: --help, --json, the device
  // list), so a failed write is seen there with its errno; a terminal stays line-buffered.
  static char stdoutBuffer[1 << 16];  // glibc ignores the size of a buffer it allocates itself
  if (!isatty(fileno(stdout))) setvbuf(stdout, stdoutBuffer, _IOFBF, sizeof stdoutBuffer);
  std::vector<std::string> args(argv + 1, argv + argc);
  CliArgs cli;
  std::string error;
  if (!parseCli(args, &cli, &error)) {
    fprintf(stderr, "raytex: %s\n", error.c_str());
    return checkedExit(2, stdout);
  }
  return checkedExit(runGuarded([&] { return runCommand(cli); }), stdout);
}
