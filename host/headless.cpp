#include "headless.h"

#include "scene_limits.h"

#include "gpu_scene.h"
#include "output_file.h"
#include "parser.h"
#include "renderer.h"

#include <algorithm>
#include <new>
#include <cmath>
#include <cstdio>

double lapMs(std::chrono::steady_clock::time_point& start) {
  std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
  double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

void savePng(const std::string& output, const ImageRGBA8& image, size_t nonFinite) {
  if (nonFinite > 0) fprintf(stderr, "warning: %zu non-finite colour values (written as black)\n", nonFinite);
  std::vector<uint8_t> png = encodePng(image);
  if (png.empty()) throw Error(ErrorKind::Internal, "cannot encode PNG for '" + output + "'");
  if (!output.empty()) writeOutput(output, png);
}

namespace {

// Parses the scene, loads its images and packs it: bad input fails before any Vulkan.
GpuScene prepareScene(const RenderOptions& options, Scene* scene, HeadlessRender* out) {
  *scene = parseSceneFile(options.scene, ReadPolicy{options.allowRead});
  out->job = resolveJob(options, scene->render, 1);
  checkOutput(options.output, *scene);
  PackOptions pack;
  pack.mipmaps = out->job.filterBox;
  pack.maxImageMiB = options.maxImageMiB;
  GpuScene gpuScene = buildGpuScene(*scene, out->job.width, out->job.height, pack);
  out->imageBytes = imageUploadBytes(gpuScene.images, pack.mipmaps);
  return gpuScene;
}

// Whether samples go one dispatch each: where together they would pass lavapipe's loop limit
// (kMaxLoopIterations), the progressive kernel adds them one at a time, the same image bit for
// bit. A sphere tree's walks are not known before they run: its samples always go one at a time.
bool samplesPerDispatch(const Renderer& renderer, const Scene& scene, const GpuScene& gpuScene, const RenderJob& job) {
  return renderer.device.lavapipe && job.samplesPerPixel > 1 &&
         (gpuScene.shape.sphereTree != SPHERE_TREE_NONE ||
          job.samplesPerPixel * loopIterationsPerSample(scene) > kMaxLoopIterations);
}

// The kernel built around the scene's values (the camera is fixed), and tile kernels where they
// pay within this render's samples (tile_kernels.h), or, steady, wherever they save (bench: the
// frame a long render or the viewer gets).
void preparePipelines(Renderer& renderer, const GpuScene& gpuScene, const RenderJob& job, bool perSample,
                      double samples) {
  KernelOptions kernel;
  kernel.filterBox = job.filterBox;
  kernel.samplesPerSide = job.samplesPerSide;
  kernel.progressive = perSample;
  kernel.bakeValues = true;
  const KernelKey key = kernelKey(gpuScene, kernel);
  preparePipeline(renderer, key);
  if (!renderer.device.lavapipe || bandCount(renderer) != 1) return;
  const TilePlan plan = planTileKernels(gpuScene, {key.shape.sphereKinds, key.shape.planeKinds});
  if (tileKernelsPay(plan, samples)) prepareTileKernels(renderer, key, plan);
}

// One band of the image, every sample; its GPU time.
double renderBand(Renderer& renderer, uint32_t firstRow, bool perSample, uint32_t samplesPerPixel) {
  selectBand(renderer, firstRow);
  if (!perSample) {
    renderFrame(renderer);
    return renderer.lastFrameMs;
  }
  double ms = 0.0;
  for (uint32_t i = 0; i < samplesPerPixel; ++i) {
    renderSample(renderer, i);
    ms += renderer.lastFrameMs;
  }
  return ms;
}

// Reads the selected band back into its rows of `image` (the whole image when it is one band),
// as 8-bit sRGB.
void keepBand(Renderer& renderer, const RenderJob& job, ImageRGBA8& image, size_t* nonFinite) {
  readbackFrame(renderer);
  ImageRGBA8 band = encodeSrgb(framePixels(renderer), int(job.width), int(bandHeight(renderer)), nonFinite);
  if (band.height == image.height) {
    image = std::move(band);
    return;
  }
  std::copy(band.pixels.begin(), band.pixels.end(),
            image.pixels.begin() + ptrdiff_t(size_t(renderer.bandFirstRow) * job.width * 4));
}

// Renders the image, then `extraFrames` more frames of it (timed, into out->frameMs). An
// image over the device's storage-buffer range is rendered in bands of rows, each read back as
// soon as it is done (renderer.h, bandRows).
ImageRGBA8 renderImage(Renderer& renderer, bool perSample, uint32_t extraFrames, HeadlessRender* out,
                       std::chrono::steady_clock::time_point& t) {
  const RenderJob& job = out->job;
  const uint32_t bands = bandCount(renderer);
  ImageRGBA8 image{int(job.width), int(job.height), {}};
  if (bands > 1) image.pixels.resize(size_t(job.width) * job.height * 4);
  for (uint32_t b = 0; b < bands; ++b) {
    renderBand(renderer, b * renderer.bandRows, perSample, job.samplesPerPixel);
    if (bands > 1) keepBand(renderer, job, image, &out->nonFinite);
  }
  out->times.firstDispatch = lapMs(t);  // several bands: their readbacks too
  for (uint32_t i = 0; i < extraFrames; ++i) {
    double ms = 0.0;
    for (uint32_t b = 0; b < bands; ++b) ms += renderBand(renderer, b * renderer.bandRows, perSample, job.samplesPerPixel);
    out->frameMs.push_back(ms);
  }
  t = std::chrono::steady_clock::now();  // the extra frames are not part of a render
  if (bands == 1) keepBand(renderer, job, image, &out->nonFinite);
  out->times.readback = lapMs(t);
  return image;
}

// Upload, pipelines and the image read back, on a renderer created by the caller.
ImageRGBA8 renderPrepared(Renderer& renderer, const Scene& scene, const GpuScene& gpuScene, uint32_t extraFrames,
                          HeadlessRender* out, bool steady, std::chrono::steady_clock::time_point& t) {
  const RenderJob& job = out->job;
  PhaseTimes& times = out->times;
  const int errorsBefore = renderer.device.validationErrors;
  if (renderer.device.lavapipe) checkLoopLimit(scene);
  const bool perSample = samplesPerDispatch(renderer, scene, gpuScene, job);
  renderer.accumulate = perSample;
  uploadScene(renderer, gpuScene);
  times.upload = lapMs(t);
  preparePipelines(renderer, gpuScene, job, perSample,
                   steady ? INFINITY : double(job.samplesPerPixel) * (1 + extraFrames));
  times.pipeline = lapMs(t);
  ImageRGBA8 image = renderImage(renderer, perSample, extraFrames, out, t);
  if (renderer.device.validationErrors > errorsBefore)
    throw VulkanError(std::to_string(renderer.device.validationErrors - errorsBefore) + " Vulkan validation error(s)");
  return image;
}

// Everything on the device: creation, then renderPrepared.
ImageRGBA8 renderOnDevice(Renderer& renderer, const RenderOptions& options, const Scene& scene,
                          const GpuScene& gpuScene, uint32_t extraFrames, HeadlessRender* out, bool steady,
                          std::chrono::steady_clock::time_point& t) {
  createRenderer(renderer, {options.device, options.validate});
  out->deviceName = renderer.device.properties.deviceName;
  out->times.device = lapMs(t);
  return renderPrepared(renderer, scene, gpuScene, extraFrames, out, steady, t);
}

// One scene of a batch on the batch's renderer: parsed, rendered and written.
void renderBatchItem(Renderer& renderer, const RenderOptions& options, const BatchItem& item) {
  RenderOptions one = options;
  one.scene = item.scene;
  one.scenes = {item.scene};
  one.output = item.output;
  HeadlessRender out;
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  Scene scene;
  const GpuScene gpuScene = prepareScene(one, &scene, &out);
  ImageRGBA8 image = renderPrepared(renderer, scene, gpuScene, 0, &out, false, t);
  savePng(one.output, image, out.nonFinite);
}

}  // namespace

void renderHeadless(const RenderOptions& options, uint32_t extraFrames, HeadlessRender* out, bool steady) {
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  Scene scene;
  const GpuScene gpuScene = prepareScene(options, &scene, out);
  out->times.parse = lapMs(t);
  Renderer renderer;
  ImageRGBA8 image;
  try {
    image = renderOnDevice(renderer, options, scene, gpuScene, extraFrames, out, steady, t);
  } catch (...) {
    destroyRenderer(renderer);
    throw;
  }
  destroyRenderer(renderer);
  t = std::chrono::steady_clock::now();  // device teardown is not a phase
  savePng(options.output, image, out->nonFinite);
  out->times.encode = lapMs(t);
}

BatchResult renderBatch(const RenderOptions& options, const std::vector<BatchItem>& items) {
  Renderer renderer;
  BatchResult result;
  try {
    createRenderer(renderer, {options.device, options.validate});
    for (const BatchItem& item : items) {
      try {
        renderBatchItem(renderer, options, item);
      } catch (const Error& e) {
        fprintf(stderr, "%s\n", errorLine(e).c_str());
        if (result.failed++ == 0) result.firstFailure = e.kind;
      } catch (const std::bad_alloc&) {
        fprintf(stderr, "raytex: out of memory rendering '%s'\n", item.scene.c_str());
        if (result.failed++ == 0) result.firstFailure = ErrorKind::OutOfMemory;
      }
    }
  } catch (...) {
    destroyRenderer(renderer);
    throw;
  }
  destroyRenderer(renderer);
  return result;
}
