#include "headless.h"

#include "scene_limits.h"

#include "exit_status.h"
#include "gpu_scene.h"
#include "output_file.h"
#include "parser.h"
#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

double lapMs(std::chrono::steady_clock::time_point& start) {
  std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
  double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

int savePng(const std::string& output, const ImageRGBA8& image, size_t nonFinite) {
  if (nonFinite > 0) fprintf(stderr, "warning: %zu non-finite colour values (written as black)\n", nonFinite);
  std::vector<uint8_t> png = encodePng(image);
  if (png.empty()) {
    fprintf(stderr, "raytex: cannot encode PNG for '%s'\n", output.c_str());
    return 1;
  }
  if (output.empty()) return 0;
  try {
    writeFileAtomic(output, png);
  } catch (const std::exception& e) {
    fprintf(stderr, "raytex: %s\n", e.what());
    return 1;
  }
  return 0;
}

int renderHeadless(const RenderOptions& options, uint32_t extraFrames, HeadlessRender* out, bool steady) {
  PhaseTimes& times = out->times;
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  // Parse and load images before touching Vulkan: bad input fails fast.
  GpuScene gpuScene;
  Scene scene;
  try {
    scene = parseSceneFile(options.scene, ReadPolicy{options.allowRead});
    std::string error;
    if (!resolveJob(options, scene.render, 1, &out->job, &error)) {
      fprintf(stderr, "raytex: %s\n", error.c_str());
      return 2;
    }
    if (std::string clash = outputClash(options.output, scene); !clash.empty()) {
      fprintf(stderr, "raytex: %s\n", clash.c_str());
      return 2;
    }
    PackOptions pack;
    pack.mipmaps = out->job.filterBox;
    pack.maxImageMiB = options.maxImageMiB;
    gpuScene = buildGpuScene(scene, out->job.width, out->job.height, pack);
    out->imageBytes = imageUploadBytes(gpuScene.images, pack.mipmaps);
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  times.parse = lapMs(t);

  const RenderJob& job = out->job;
  Renderer renderer;
  ImageRGBA8 image;
  try {
    createRenderer(renderer, {options.device, options.validate});
    out->deviceName = renderer.device.properties.deviceName;
    times.device = lapMs(t);
    if (renderer.device.lavapipe) checkLoopLimit(scene);
    // Samples that together would pass lavapipe's loop limit (kMaxLoopIterations) are added one
    // dispatch at a time by the progressive kernel: the same image, bit for bit. A sphere tree's
    // walks are not known before they run: its samples always go one at a time.
    const bool perSample = renderer.device.lavapipe && job.samplesPerPixel > 1 &&
                           (gpuScene.shape.sphereTree != SPHERE_TREE_NONE ||
                            job.samplesPerPixel * loopIterationsPerSample(scene) > kMaxLoopIterations);
    renderer.accumulate = perSample;
    uploadScene(renderer, gpuScene);
    times.upload = lapMs(t);
    // The camera is fixed: the kernel is built around the scene's values where it is small.
    KernelOptions kernel;
    kernel.filterBox = job.filterBox;
    kernel.samplesPerSide = job.samplesPerSide;
    kernel.progressive = perSample;
    kernel.bakeValues = true;
    const KernelKey key = kernelKey(gpuScene, kernel);
    preparePipeline(renderer, key);
    if (renderer.device.lavapipe && bandCount(renderer) == 1) {
      // Tile kernels where they pay within this render's samples (tile_kernels.h), or, steady,
      // wherever they save (bench: the frame a long render or the viewer gets).
      const TilePlan plan = planTileKernels(gpuScene, {key.shape.sphereKinds, key.shape.planeKinds});
      const double samples = steady ? INFINITY : double(job.samplesPerPixel) * (1 + extraFrames);
      if (tileKernelsPay(plan, samples)) prepareTileKernels(renderer, key, plan);
    }
    times.pipeline = lapMs(t);
    auto renderBand = [&](uint32_t firstRow) {  // one band of the image; its GPU time
      selectBand(renderer, firstRow);
      if (!perSample) {
        renderFrame(renderer);
        return renderer.lastFrameMs;
      }
      double ms = 0.0;
      for (uint32_t i = 0; i < job.samplesPerPixel; ++i) {
        renderSample(renderer, i);
        ms += renderer.lastFrameMs;
      }
      return ms;
    };
    // An image over the device's storage-buffer range is rendered in bands of rows, each read
    // back and converted to 8 bits as soon as it is done (renderer.h, bandRows).
    const uint32_t bands = bandCount(renderer);
    out->nonFinite = 0;
    if (bands > 1) {
      image.width = int(job.width);
      image.height = int(job.height);
      image.pixels.resize(size_t(job.width) * job.height * 4);
    }
    auto keepBand = [&] {
      readbackFrame(renderer);
      size_t nonFinite = 0;
      ImageRGBA8 band = encodeSrgb(framePixels(renderer), int(job.width), int(bandHeight(renderer)), &nonFinite);
      out->nonFinite += nonFinite;
      if (bands == 1) {
        image = std::move(band);
        return;
      }
      std::copy(band.pixels.begin(), band.pixels.end(),
                image.pixels.begin() + ptrdiff_t(size_t(renderer.bandFirstRow) * job.width * 4));
    };
    for (uint32_t b = 0; b < bands; ++b) {
      renderBand(b * renderer.bandRows);
      if (bands > 1) keepBand();
    }
    times.firstDispatch = lapMs(t);  // several bands: their readbacks too
    for (uint32_t i = 0; i < extraFrames; ++i) {
      double ms = 0.0;
      for (uint32_t b = 0; b < bands; ++b) ms += renderBand(b * renderer.bandRows);
      out->frameMs.push_back(ms);
    }
    t = std::chrono::steady_clock::now();  // the extra frames are not part of a render
    if (bands == 1) keepBand();
    times.readback = lapMs(t);
    int validationErrors = renderer.device.validationErrors;
    destroyRenderer(renderer);
    if (validationErrors > 0) {
      fprintf(stderr, "raytex: %d Vulkan validation error(s)\n", validationErrors);
      return 1;
    }
  } catch (const SceneError& e) {  // a limit of the device's driver
    fprintf(stderr, "%s\n", e.what());
    destroyRenderer(renderer);
    return 2;
  } catch (const std::exception& e) {
    fprintf(stderr, "raytex: %s\n", exceptionText(e).c_str());
    destroyRenderer(renderer);
    return 1;
  }
  t = std::chrono::steady_clock::now();  // device teardown is not a phase
  if (int rc = savePng(options.output, image, out->nonFinite)) return rc;
  times.encode = lapMs(t);
  return 0;
}
