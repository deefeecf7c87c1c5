#include "headless.h"

#include "gpu_scene.h"
#include "image_io.h"
#include "parser.h"
#include "renderer.h"

#include <chrono>
#include <cstdio>

namespace {

using Clock = std::chrono::steady_clock;

// Milliseconds since `start`, and restarts it: one call per phase.
double lap(Clock::time_point& start) {
  Clock::time_point now = Clock::now();
  double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

}  // namespace

int renderHeadless(const RenderOptions& options, uint32_t extraFrames, bool writeFile, HeadlessRender* out) {
  PhaseTimes& times = out->times;
  Clock::time_point t = Clock::now();
  // Parse and load images before touching Vulkan: bad input fails fast.
  GpuScene gpuScene;
  try {
    Scene scene = parseSceneFile(options.scene);
    std::string error;
    if (!resolveJob(options, scene.render, 1, &out->job, &error)) {
      fprintf(stderr, "raytex: %s\n", error.c_str());
      return 2;
    }
    gpuScene = buildGpuScene(scene, out->job.width, out->job.height, out->job.filterBox);
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  times.parse = lap(t);

  const RenderJob& job = out->job;
  Renderer renderer;
  ImageRGBA8 image;
  try {
    createRenderer(renderer, {options.device, options.validate});
    out->deviceName = renderer.device.properties.deviceName;
    times.device = lap(t);
    uploadScene(renderer, gpuScene);
    times.upload = lap(t);
    preparePipeline(renderer, {gpuScene.shape, OUTPUT_SHADED, uint32_t(job.filterBox ? FILTER_BOX : FILTER_POINT),
                               job.samplesPerSide});
    times.pipeline = lap(t);
    renderFrame(renderer);
    times.firstDispatch = lap(t);
    for (uint32_t i = 0; i < extraFrames; ++i) {
      renderFrame(renderer);
      out->frameMs.push_back(renderer.lastFrameMs);
    }
    t = Clock::now();  // the extra frames are not part of a render
    readbackFrame(renderer);
    image = encodeSrgb(framePixels(renderer), int(job.width), int(job.height), &out->nonFinite);
    times.readback = lap(t);
    int validationErrors = renderer.device.validationErrors;
    destroyRenderer(renderer);
    if (validationErrors > 0) {
      fprintf(stderr, "raytex: %d Vulkan validation error(s)\n", validationErrors);
      return 1;
    }
  } catch (const std::exception& e) {
    fprintf(stderr, "raytex: %s\n", e.what());
    destroyRenderer(renderer);
    return 1;
  }
  t = Clock::now();  // device teardown is not a phase
  if (out->nonFinite > 0)
    fprintf(stderr, "warning: %zu non-finite colour values (written as black)\n", out->nonFinite);
  std::vector<uint8_t> png = encodePng(image);
  if (png.empty()) {
    fprintf(stderr, "raytex: cannot encode PNG for '%s'\n", options.output.c_str());
    return 1;
  }
  if (writeFile) {
    try {
      writeFileAtomic(options.output, png);
    } catch (const std::exception& e) {
      fprintf(stderr, "raytex: %s\n", e.what());
      return 1;
    }
  }
  times.encode = lap(t);
  return 0;
}
