#include "headless.h"

#include "kernel_plan.h"
#include "scene_limits.h"

#include "gpu_scene.h"
#include "atomic_file.h"
#include "parser.h"
#include "render_files.h"
#include "scene_notes.h"
#include "renderer.h"

#include <algorithm>
#include <memory>
#include <new>
#include <optional>
#include <cmath>
#include <cstdio>

double lapMs(std::chrono::steady_clock::time_point& start) {
  std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
  double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

namespace {

// Parses the scene and resolves its job: bad input fails before any Vulkan.
void parseJob(const RenderOptions& options, Scene* scene, RenderJob* job) {
  *scene = parseSceneFile(options.scene, readPolicyOf(options));
  printSceneNotes(*scene, stderr);
  *job = resolveJob(options, scene->render, 1);
}

// Loads the scene's images and packs it for the device.
GpuScene packScene(const RenderOptions& options, const Scene& scene, HeadlessRender* out) {
  PackOptions pack;
  pack.mipmaps = out->job.filter != TextureFilter::Point;
  pack.maxImageMiB = options.maxImageMiB;
  GpuScene gpuScene = buildGpuScene(scene, out->job.width, out->job.height, pack);
  out->imageBytes = imageUploadBytes(gpuScene.images, pack.mipmaps);
  return gpuScene;
}

// Parses the scene, checks the output plan (nothing is written before), loads its images and
// packs it.
GpuScene prepareScene(const RenderOptions& options, Scene* scene, HeadlessRender* out) {
  parseJob(options, scene, &out->job);
  checkRenderOutputs(options, out->job, *scene);
  return packScene(options, *scene, out);
}

// The kernel built around the scene's values (the camera is fixed), and the kernel plan's kernels
// for this render's samples (kernel_plan.h), or, steady, for the frame a long render gets (bench).
void preparePipelines(Renderer& renderer, const GpuScene& gpuScene, const RenderJob& job, bool perSample,
                      double samples) {
  KernelOptions kernel;
  kernel.textureFilter = kernelFilter(job.filter);
  kernel.imageFilter = kernelImageFilter(job.imageFilter);
  kernel.samplesPerSide = job.samplesPerSide;
  kernel.progressive = perSample;
  kernel.bakeValues = true;
  prepareFrameKernels(renderer, gpuScene, kernelKey(gpuScene, kernel), samples);
}

// One band of the image, every sample; its GPU time. Adds the samples the coverage filter's
// edge pass shaded again to `edgeSamples`.
double renderBand(Renderer& renderer, uint32_t firstRow, bool perSample, uint32_t samplesPerPixel,
                  uint64_t& edgeSamples) {
  selectBand(renderer, firstRow);
  if (!perSample) {
    renderFrame(renderer);
    edgeSamples += edgePixelCount(renderer);
    return renderer.lastFrameMs;
  }
  double ms = 0.0;
  for (uint32_t i = 0; i < samplesPerPixel; ++i) {
    renderSample(renderer, i);
    edgeSamples += edgePixelCount(renderer);
    ms += renderer.lastFrameMs;
  }
  return ms;
}

// The render's output files, opened when the first rows come back: --metadata full carries
// the render time up to then (the whole render for an image of one band).
struct RenderOutput {
  const RenderOptions& options;
  std::chrono::steady_clock::time_point start;  // the scene's parse
  std::unique_ptr<ImageWriter> files;
  glm::dvec3 eye{0.0};  // added to the position pass (world_position.h)
};

// The selected band's passes in the order of options.passes, as ImageWriter takes them; the
// position pass in world coordinates, held in `world`.
std::vector<const float*> bandPasses(const Renderer& renderer, const RenderOutput& output, std::vector<float>& world) {
  std::vector<const float*> planes;
  for (Pass pass : output.options.passes) {
    const float* plane = passPixels(renderer, pass);
    if (pass == Pass::Position) {
      world = worldPositions(plane, size_t(renderer.width) * bandHeight(renderer), output.eye);
      plane = world.data();
    }
    planes.push_back(plane);
  }
  return planes;
}

// Reads the selected band back and writes its rows to the output files.
void keepBand(Renderer& renderer, HeadlessRender* out, RenderOutput& output) {
  readbackFrame(renderer);
  if (!output.files) {
    const RenderFacts facts{out->deviceName, std::chrono::duration<double, std::milli>(
                                                 std::chrono::steady_clock::now() - output.start).count()};
    const Metadata metadata = renderMetadata(output.options, out->job, facts);
    output.files = std::make_unique<ImageWriter>(renderOutputSpec(output.options, out->job, metadata));
  }
  std::vector<float> world;
  output.files->writeBand(int(renderer.bandFirstRow), int(bandHeight(renderer)), framePixels(renderer),
                          bandPasses(renderer, output, world));
}

// Renders the image, then `extraFrames` more frames of it (timed, into out->frameMs). An
// image over the device's storage-buffer range is rendered in bands of rows, each read back and
// written as soon as it is done (renderer.h, bandRows).
void renderImage(Renderer& renderer, bool perSample, uint32_t extraFrames, HeadlessRender* out,
                 RenderOutput& output, std::chrono::steady_clock::time_point& t) {
  const RenderJob& job = out->job;
  const uint32_t bands = bandCount(renderer);
  for (uint32_t b = 0; b < bands; ++b) {
    renderBand(renderer, b * renderer.bandRows, perSample, job.samplesPerPixel, out->edgeSamples);
    if (bands > 1) keepBand(renderer, out, output);
  }
  out->times.firstDispatch = lapMs(t);  // several bands: their readbacks and writes too
  for (uint32_t i = 0; i < extraFrames; ++i) {
    double ms = 0.0;
    uint64_t edgeSamples = 0;
    for (uint32_t b = 0; b < bands; ++b)
      ms += renderBand(renderer, b * renderer.bandRows, perSample, job.samplesPerPixel, edgeSamples);
    out->frameMs.push_back(ms);
  }
  t = std::chrono::steady_clock::now();  // the extra frames are not part of a render
  if (bands == 1) keepBand(renderer, out, output);
  out->times.readback = lapMs(t);
}

// Upload, pipelines and the image read back into `output`, on a renderer created by the caller.
void renderPrepared(Renderer& renderer, const Scene& scene, const GpuScene& gpuScene, uint32_t extraFrames,
                    HeadlessRender* out, RenderOutput& output, bool steady, std::chrono::steady_clock::time_point& t) {
  const RenderJob& job = out->job;
  PhaseTimes& times = out->times;
  const int errorsBefore = renderer.device.validationErrors;
  renderer.passMask = passMask(output.options.passes);
  renderer.coverage = job.filter == TextureFilter::Coverage;
  if (renderer.device.lavapipe) checkLoopLimit(scene, loopTraces(renderer.coverage));
  output.eye = scene.camera.eye;
  const bool perSample = samplesPerDispatch(renderer, scene, gpuScene, job);
  renderer.accumulate = perSample;
  uploadScene(renderer, gpuScene);
  times.upload = lapMs(t);
  preparePipelines(renderer, gpuScene, job, perSample,
                   steady ? INFINITY : double(job.samplesPerPixel) * (1 + extraFrames));
  times.pipeline = lapMs(t);
  renderImage(renderer, perSample, extraFrames, out, output, t);
  if (renderer.device.validationErrors > errorsBefore)
    throw VulkanError(std::to_string(renderer.device.validationErrors - errorsBefore) + " Vulkan validation error(s)");
}

// Makes the output files visible, with a warning for values not written as given (colour
// values written as black, values clamped to the half range).
void finishOutput(RenderOutput& output, HeadlessRender* out) {
  output.files->finish();
  out->nonFinite = output.files->nonFinite();
  printOutputWarnings(*output.files, stderr);
}

// Everything on the device: creation, then renderPrepared.
void renderOnDevice(Renderer& renderer, const RenderOptions& options, const Scene& scene, const GpuScene& gpuScene,
                    uint32_t extraFrames, HeadlessRender* out, RenderOutput& output, bool steady,
                    std::chrono::steady_clock::time_point& t) {
  createRenderer(renderer, {options.device, options.validate});
  out->deviceName = renderer.device.properties.deviceName;
  out->times.device = lapMs(t);
  renderPrepared(renderer, scene, gpuScene, extraFrames, out, output, steady, t);
}

// One scene of a batch, parsed before anything renders: its options (its own scene and output),
// scene and job, or the failure its parse gave.
struct BatchScene {
  RenderOptions options;
  Scene scene;
  HeadlessRender out;
  std::optional<Error> failure;
};

// Every scene parsed (a failure kept for its turn), then the plan of the whole batch checked:
// no image of one scene may replace another's, or any file any scene reads.
std::vector<BatchScene> prepareBatch(const RenderOptions& options, const std::vector<BatchItem>& items) {
  std::vector<BatchScene> scenes(items.size());
  OutputPlan plan;
  for (size_t i = 0; i < items.size(); ++i) {
    BatchScene& s = scenes[i];
    s.options = options;
    s.options.scene = items[i].scene;
    s.options.scenes = {items[i].scene};
    s.options.output = items[i].output;
    try {
      parseJob(s.options, &s.scene, &s.out.job);
      mergePlan(plan, planRender(s.options, s.out.job, s.scene, true));
    } catch (const Error& e) {
      s.failure = e;
      plan.reads.push_back({items[i].scene, "the scene file"});
    } catch (const std::bad_alloc&) {
      s.failure = Error(ErrorKind::OutOfMemory, "out of memory reading '" + items[i].scene + "'");
      plan.reads.push_back({items[i].scene, "the scene file"});
    }
  }
  checkPlan(plan);
  return scenes;
}

// One scene of a batch on the batch's renderer: packed, rendered and written.
void renderBatchScene(Renderer& renderer, BatchScene& s) {
  if (s.failure) throw *s.failure;
  s.out.deviceName = renderer.device.properties.deviceName;
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  RenderOutput output{s.options, t, nullptr};
  const GpuScene gpuScene = packScene(s.options, s.scene, &s.out);
  renderPrepared(renderer, s.scene, gpuScene, 0, &s.out, output, false, t);
  finishOutput(output, &s.out);
}

}  // namespace

void renderHeadless(const RenderOptions& given, uint32_t extraFrames, HeadlessRender* out, bool steady) {
  RenderOptions options = given;
  if (options.output.empty()) options.output = "/dev/null";  // bench without -o: encoded, for its time
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  RenderOutput output{options, t, nullptr};
  Scene scene;
  const GpuScene gpuScene = prepareScene(options, &scene, out);
  out->times.parse = lapMs(t);
  Renderer renderer;
  try {
    renderOnDevice(renderer, options, scene, gpuScene, extraFrames, out, output, steady, t);
  } catch (...) {
    destroyRenderer(renderer);
    throw;
  }
  destroyRenderer(renderer);
  t = std::chrono::steady_clock::now();  // device teardown is not a phase
  finishOutput(output, out);
  out->times.encode = lapMs(t);
}

BatchResult renderBatch(const RenderOptions& options, const std::vector<BatchItem>& items) {
  std::vector<BatchScene> scenes = prepareBatch(options, items);
  Renderer renderer;
  BatchResult result;
  try {
    createRenderer(renderer, {options.device, options.validate});
    for (BatchScene& scene : scenes) {
      try {
        renderBatchScene(renderer, scene);
      } catch (const Error& e) {
        fprintf(stderr, "%s\n", errorLine(e).c_str());
        if (result.failed++ == 0) result.firstFailure = e.kind;
      } catch (const std::bad_alloc&) {
        fprintf(stderr, "raytex: out of memory rendering '%s'\n", scene.options.scene.c_str());
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
