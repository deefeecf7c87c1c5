#include "viewer.h"

#include "input.h"
#include "kernel_warm_up.h"
#include "overlay.h"
#include "viewer_state.h"
#include "window.h"

#include "kernel_plan.h"
#include "median.h"
#include "parser.h"
#include "render_files.h"
#include "renderer.h"
#include "scene_limits.h"
#include "scene_notes.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

// How the viewer packs a scene, and what a reloaded scene's images must pass before it replaces
// the scene on screen.
struct ImageLimits {
  PackOptions pack;  // every material (a key switches to it), mip chains for the filtered kernel
  uint32_t maxImageDimension2D = 0;  // the device's
  bool lavapipe = false;  // its driver's loop limit applies (scene_limits.h)
  uint32_t traces = 1;    // checkLoopLimit's: loopTraces
};

// Modification times of the scene's files (an unreadable file counts as changed).
std::vector<std::filesystem::file_time_type> fileTimes(const Scene& scene) {
  std::vector<std::filesystem::file_time_type> times;
  for (const std::string& f : scene.files) {
    std::error_code ec;
    times.push_back(std::filesystem::last_write_time(f, ec));
  }
  return times;
}

// Re-parses the scene when one of its files changed, and loads its images. An error (a parse
// error with its file:line:col, an image refused or over the device's limits, the loop limit)
// is printed and the last good scene stays; it is kept (lastGood) until the reloaded scene has
// rendered, in case the kernel fails it.
void reloadIfChanged(ViewerState& state, const std::string& path, const ReadPolicy& policy,
                     std::vector<std::filesystem::file_time_type>& times, const ImageLimits& limits) {
  std::vector<std::filesystem::file_time_type> now = fileTimes(state.scene);
  if (now == times) return;
  times = now;
  try {
    Scene scene = parseSceneFile(path, policy);
    times = fileTimes(scene);
    if (limits.lavapipe) checkLoopLimit(scene, limits.traces);
    GpuScene gpuScene = buildGpuScene(scene, 1, 1, limits.pack);
    std::string over = imagesOverDeviceLimits(gpuScene.images, limits.maxImageDimension2D);
    if (!over.empty()) throw VulkanError(over);
    printSceneNotes(scene, stderr);
    if (!state.lastGood)
      state.lastGood = LastGoodScene{std::move(state.scene), state.orbit, state.selection, {}, false};
    state.scene = std::move(scene);
    state.reloaded = std::move(gpuScene);
    state.orbit = orbitOf(state.scene.camera);
    state.dirty = true;
    state.selection = {};
    state.sceneError = false;
    say(state, "reloaded");
  } catch (const Error& e) {
    fprintf(stderr, "%s\n", errorLine(e).c_str());
    state.sceneError = true;
    state.message.clear();  // a "reloaded" before the error no longer holds
  }
}

// Samples per pixel the viewer accumulates when neither --spp nor the scene's render block
// says: 8 x 8, about a second at 60 frames per second.
constexpr uint32_t kViewerSamplesPerPixel = 64;

// F12: the image on screen, every sample in, written to options.output (the file raytex render
// writes for this view, its format and metadata included). The output plan is checked again
// (a reload may have made the output one of the scene's files); a refusal or a failed write is
// one line on stderr and in the title; the viewer goes on.
void saveScreenshot(ViewerState& state, Renderer& renderer, const RenderOptions& options, const RenderJob& job,
                    const char* settings) {
  const std::string& output = options.output;
  std::string error;
  try {
    checkRenderOutputs(options, job, state.scene);
  } catch (const Error& e) {
    error = e.what();
  }
  if (error.empty()) {
    readbackFrame(renderer);
    try {
      ImageWriter file(renderOutputSpec(options, job, renderMetadata(options, job, {})));
      file.writeBand(0, int(renderer.height), framePixels(renderer), {});
      file.finish();
    } catch (const Error& e) {
      error = e.what();
    }
  }
  if (!error.empty()) {
    fprintf(stderr, "raytex: %s\n", error.c_str());
    say(state, "not saved, see the terminal");
    return;
  }
  say(state, "wrote " + output);
  printf("raytex: wrote %s (%ux%u, %s)\n", output.c_str(), renderer.width, renderer.height, settings);
  fflush(stdout);
}

// The title: the first sphere's and plane's materials, the selection, the samples, the frame
// time, then what is passing: the point under the magnifier, a message, a scene error.
std::string title(const ViewerState& state, uint32_t samples, uint32_t target, double frameMs, double gpuMs,
                  const std::string& readout) {
  std::string t = "raytex";
  if (!state.scene.spheres.empty()) t += " | sphere: " + materialName(state.scene, state.scene.spheres[0].material);
  if (!state.scene.planes.empty()) t += " | plane: " + materialName(state.scene, state.scene.planes[0].material);
  if (state.selection.kind)
    t += " | selected: " + selectionName(state.scene, state.selection) + ": " +
         materialName(state.scene, selectedMaterial(state.scene, state.selection));
  char text[96];
  snprintf(text, sizeof(text), " | %u/%u samples | %.1f ms/frame (GPU %.1f)", samples, target, frameMs, gpuMs);
  t += text;
  if (state.uvPass) t += " | uv pass";
  if (state.split)
    t += std::string(" | split: ") + textureFilterName(state.filter) + " | " + textureFilterName(state.splitFilter);
  if (!readout.empty()) t += " | " + readout;
  if (!state.message.empty() && Clock::now() - state.messageAt < kMessageTime) t += " | " + state.message;
  if (state.sceneError) t += " | scene error, see the terminal";
  return t;
}

double msBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// Frame times for --stats and --frames, printed when the viewer quits.
struct FrameStats {
  std::vector<double> frameMs, gpuMs, presentMs, switchMs;
  void print(uint32_t width, uint32_t height) const {
    printf("raytex: %zu frames at %ux%u: median %.2f ms per frame (%.1f fps); GPU %.2f ms, present %.2f ms\n",
           frameMs.size(), width, height, median(frameMs), 1000.0 / std::max(median(frameMs), 1e-9),
           median(gpuMs), median(presentMs));
    if (!switchMs.empty())
      printf("raytex: %zu material switches: key to frame shown median %.1f ms, max %.1f ms\n", switchMs.size(),
             median(switchMs), *std::max_element(switchMs.begin(), switchMs.end()));
  }
};

// Everything the frame loop works on.
struct Viewer {
  ViewerState state;
  RenderJob job;
  PackOptions pack;  // every material, so that a key can switch to it
  Window window;
  Renderer renderer;
  FrameStats stats;
  GpuScene gpuScene;
  uint32_t target = 1;   // samples per pixel to accumulate
  uint32_t samples = 0;  // accumulated in the image on screen
  bool allKindsWarm = false;  // the all-kinds kernel of the packed scene has run (reset with each upload)
  KernelKey splitKeys[2];     // V: the kernels of the split's other method and of the job's, as packed
  std::vector<float> uv;  // U: the uv pass of the image on screen (AOV_UV, a vec4 a pixel)
  Buffer splitPixels;     // V: the other method's display pixels, read back to draw beside the job's
  std::vector<std::filesystem::file_time_type> fileTimes;
  Clock::time_point lastTitle, frameStart;
};

// The scene, the job and how to pack it: bad input fails before any window opens.
void loadScene(Viewer& v, const RenderOptions& options) {
  ViewerState& state = v.state;
  state.scene = parseSceneFile(options.scene, readPolicyOf(options));
  printSceneNotes(state.scene, stderr);
  v.job = resolveJob(options, state.scene.render, kViewerSamplesPerPixel);
  checkRenderOutputs(options, v.job, state.scene);  // F12 writes -o
  v.target = v.job.samplesPerSide * v.job.samplesPerSide;
  v.pack.mipmaps = v.job.filter != TextureFilter::Point;  // mip chains only for the filtered kernel
  v.pack.allMaterials = true;
  v.pack.maxImageMiB = options.maxImageMiB;
  state.filter = v.job.filter;
  state.splitFilter = nextFilter(v.job.filter, v.job.filter);
  state.orbit = orbitOf(state.scene.camera);
  for (size_t i = 0; i < 8 && !state.scene.planes.empty(); ++i)
    if (materialIndex(state.scene, kCourseMaterials[i]) == state.scene.planes[0].material) state.planeMaterial = int(i);
  v.fileTimes = fileTimes(state.scene);
}

// The window with its input callbacks, the device that presents to it, and its swapchain.
void openViewer(Viewer& v, const RenderOptions& options) {
  v.window.window = openWindow(int(v.job.width), int(v.job.height), "raytex");
  GLFWwindow* w = v.window.window;
  installInput(w, &v.state);
  DeviceOptions device;
  device.deviceIndex = options.device;
  device.validation = options.validate;
  device.instanceExtensions = windowInstanceExtensions();
  device.presentSupport = windowPresentSupport;
  v.renderer.accumulate = true;
  v.renderer.coverage = v.job.filter == TextureFilter::Coverage;
  createRenderer(v.renderer, device);
  if (v.renderer.device.lavapipe) checkLoopLimit(v.state.scene, loopTraces(v.renderer.coverage));
  createSwapchain(v.window, v.renderer.device);
  v.renderer.displayBgra = windowBgra(v.window);
}

// Handles input; waits when there is nothing to render, compiling meanwhile the specialised
// kernels the all-kinds one stands in for, then what a key may need next so that the switch
// shows on the next frame. The all-kinds kernel compiles once the first frame is shown.
void waitForWork(Viewer& v, bool keepRendering) {
  ViewerState& s = v.state;
  const bool busy = v.samples < v.target || s.dirty || s.cameraMoved || s.refresh || s.screenshot;
  KernelKey warm;
  if (!keepRendering && v.samples > 0 && !v.allKindsWarm) {
    const KernelKey all = allKindsKey(v.gpuScene, s.scene, v.job);
    if (!pipelineWarm(v.renderer, all)) warmPipeline(v.renderer, all);
    v.allKindsWarm = true;
    glfwPollEvents();
  } else if (busy || keepRendering) {
    glfwPollEvents();
  } else if (s.specialisedPending && pendingKernel(v.renderer, v.gpuScene, s.scene, v.job, &warm)) {
    warmPipeline(v.renderer, warm);
    glfwPollEvents();
  } else if (s.specialisedPending) {
    s.specialisedPending = !prepareViewerKernels(v.renderer, v.gpuScene, s.scene, v.job);
  } else if (nextPipelineToWarm(s.scene, v.renderer, v.job, v.gpuScene, &warm)) {
    warmPipeline(v.renderer, warm);
    glfwPollEvents();
  } else {
    glfwWaitEventsTimeout(0.25);  // wakes for the reload poll
  }
}

// What the renderer and the packing need for U and V: the uv pass, the coverage filter's edge
// list, a second accumulation set and mip chains. Changes mark the scene dirty; returns whether
// the scene must be packed again (its images with or without mip chains).
bool configureMethods(Viewer& v) {
  ViewerState& state = v.state;
  Renderer& r = v.renderer;
  auto uses = [&](TextureFilter f) { return state.filter == f || (state.split && state.splitFilter == f); };
  // On lavapipe, the coverage filter's edge pass and the uv pass (the pixel centre traced once
  // more) only within its loop limit.
  auto fits = [&](uint32_t traces) { return !r.device.lavapipe || withinLoopLimit(state.scene, traces); };
  if (uses(TextureFilter::Coverage) && !r.coverage && !fits(loopTraces(true))) {
    state.split = false;
    say(state, "no split with coverage: this scene would pass the lavapipe driver's loop limit");
  }
  const bool edges = uses(TextureFilter::Coverage);
  if (state.uvPass && !fits(loopTraces(edges) + 1)) {
    state.uvPass = false;
    say(state, "no uv pass: this scene would pass the lavapipe driver's loop limit");
  }
  const uint32_t passes = state.uvPass ? 1u << AOV_UV : 0u;
  const bool mipmaps = uses(TextureFilter::Box) || edges;
  const bool changed = passes != r.passMask || edges != r.coverage || state.split != r.secondAccumulation;
  r.passMask = passes;
  r.coverage = edges;
  r.secondAccumulation = state.split;
  const bool repack = mipmaps != v.pack.mipmaps;
  v.pack.mipmaps = mipmaps;
  if (changed || repack) state.dirty = true;
  return repack;
}

// Re-packs and uploads what changed: everything for a new size, scene file, unpacked material
// or method (U, V); camera-relative positions and material indices for a camera move or a key.
void updateScene(Viewer& v, VkExtent2D size) {
  ViewerState& state = v.state;
  // Images are decoded only with the scene (start, reload), when an object's material is not
  // packed (over MAX_MATERIALS), or when mip chains come or go; a new size re-packs the camera.
  bool unpacked = false;
  for (const Sphere& o : state.scene.spheres) unpacked = unpacked || !v.gpuScene.materialIndex.count(o.material);
  for (const Plane& o : state.scene.planes) unpacked = unpacked || !v.gpuScene.materialIndex.count(o.material);
  if (size.width != v.renderer.width || size.height != v.renderer.height || unpacked) state.dirty = true;
  const bool packedMipmaps = v.pack.mipmaps;  // the scene on the device's
  const bool repack = configureMethods(v);
  if (!state.dirty && !state.cameraMoved) return;
  if (state.dirty && state.reloaded && state.lastGood && !state.lastGood->packed) {
    state.lastGood->packed = std::move(v.gpuScene);
    state.lastGood->mipmaps = packedMipmaps;
  }
  if (state.dirty && state.reloaded && !repack) {
    v.gpuScene = std::move(*state.reloaded);
  } else if (state.dirty && (unpacked || repack || state.reloaded)) {
    v.gpuScene = buildGpuScene(state.scene, size.width, size.height, v.pack);
  }
  state.reloaded.reset();
  packCamera(v.gpuScene, state.scene, size.width, size.height);
  if (state.dirty) {
    uploadScene(v.renderer, v.gpuScene);
    v.allKindsWarm = false;  // the scene's materials or the passes may have changed
  } else {
    updateSceneBuffers(v.renderer, v.gpuScene);
  }
  state.specialisedPending = !prepareViewerKernels(v.renderer, v.gpuScene, state.scene, v.job);
  if (state.split) {
    RenderJob other = v.job;
    other.filter = state.splitFilter;
    v.splitKeys[0] = viewerKey(v.gpuScene, state.scene, other);
    v.splitKeys[1] = viewerKey(v.gpuScene, state.scene, v.job);
  }
  state.dirty = state.cameraMoved = false;
  v.samples = 0;
}

// U: the uv pass the first sample wrote, kept for the frames that add the others.
void keepUvPass(Viewer& v) {
  readbackFrame(v.renderer);
  const float* uv = passPixels(v.renderer, Pass::Uv);
  v.uv.assign(uv, uv + size_t(v.renderer.width) * v.renderer.height * 4);
}

// V: the sample of the split's other method into the second accumulation set, then the job's
// own into the first, which F12 reads.
void renderSplitSample(Viewer& v) {
  preparePipeline(v.renderer, v.splitKeys[0]);
  swapAccumulation(v.renderer);
  try {
    renderSample(v.renderer, v.samples);
  } catch (const LoopBudgetError&) {
    swapAccumulation(v.renderer);  // the job's set stays the first
    throw;
  }
  swapAccumulation(v.renderer);
  preparePipeline(v.renderer, v.splitKeys[1]);
  renderSample(v.renderer, v.samples);
}

// The scene before a reload back on screen (lastGood), the reloaded one's kernel having failed
// with `error`: printed, and the title says so, as for the other reload errors. The scene's
// files as they are now count as seen: the next change to one of them reloads.
void restoreLastGood(Viewer& v, const Error& error) {
  ViewerState& state = v.state;
  LastGoodScene& good = *state.lastGood;
  fprintf(stderr, "%s\n", errorLine(error).c_str());
  state.scene = std::move(good.scene);
  state.orbit = good.orbit;
  state.selection = good.selection;
  v.gpuScene = std::move(*good.packed);
  v.pack.mipmaps = good.mipmaps;  // configureMethods packs it again where the methods need otherwise
  state.lastGood.reset();
  state.reloaded.reset();
  state.dirty = true;
  state.sceneError = true;
  state.message.clear();  // the "reloaded" no longer holds
  v.fileTimes = fileTimes(state.scene);
}

// Adds the next sample to the image on screen (both methods' with the split); false when the
// kernel failed a reloaded scene and the last good scene came back instead.
bool addSample(Viewer& v) {
  try {
    if (v.state.split) renderSplitSample(v);
    else renderSample(v.renderer, v.samples);
  } catch (const LoopBudgetError& e) {
    if (!v.state.lastGood || !v.state.lastGood->packed) throw;
    restoreLastGood(v, e);
    return false;
  }
  ++v.samples;
  // A reloaded scene that rendered a sample is the good one from now on: the next reload falls
  // back to it, even when it comes before this one has every sample.
  v.state.lastGood.reset();
  return true;
}

// The image to the window, with the overlays that are on drawn over a copy of it: the uv pass,
// the magnifier, the help. False when the swapchain must be re-created.
bool showImage(Viewer& v) {
  const ViewerState& s = v.state;
  if (!s.help && !s.magnifier && !s.uvPass && !s.split) return presentPixels(v.window, v.renderer.device, v.renderer.display);
  if (s.split) readImagePixels(v.renderer.device, v.renderer.otherDisplay, v.splitPixels);
  return presentComposed(v.window, v.renderer.device, v.renderer.display, [&](uint32_t* pixels, uint32_t w, uint32_t h) {
    OverlayPixels image{pixels, int(w), int(h), v.renderer.displayBgra != 0};
    if (s.split) drawSplit(image, static_cast<const uint32_t*>(v.splitPixels.data), int(std::lround(s.splitAt * w)));
    if (s.uvPass && v.uv.size() == size_t(w) * h * 4) drawUvPass(image, v.uv.data());
    if (s.magnifier) drawMagnifier(image, int(s.cursorX), int(s.cursorY));
    if (s.help) drawTextBox(image, keyHelpLines());
  });
}

// Adds a sample while the image lacks some, writes the F12 screenshot once it has all, and
// presents the image when it changed or the window was exposed.
void renderAndShow(Viewer& v, const RenderOptions& options) {
  ViewerState& state = v.state;
  if (options.frames && v.samples == v.target) v.samples = 0;  // --frames: keep rendering
  const bool render = v.samples < v.target;
  if (render) {
    if (!addSample(v)) return;
    v.stats.gpuMs.push_back(v.renderer.lastFrameMs);
    if (v.samples == 1 && state.uvPass) keepUvPass(v);
  }
  if (state.screenshot && v.samples == v.target) {
    // Every sample in: bit-identical to raytex render's image with these settings.
    state.screenshot = false;
    const std::string settings = std::to_string(v.target) + " spp, filter " + textureFilterName(v.job.filter);
    saveScreenshot(state, v.renderer, options, v.job, settings.c_str());
  }
  if (!render && !state.refresh) {
    v.frameStart = Clock::now();
    return;
  }
  state.refresh = false;
  const Clock::time_point presentStart = Clock::now();
  if (!showImage(v)) {
    createSwapchain(v.window, v.renderer.device);
    v.renderer.displayBgra = windowBgra(v.window);
  }
  const Clock::time_point now = Clock::now();
  if (state.switchedAt) v.stats.switchMs.push_back(msBetween(*state.switchedAt, now));
  state.switchedAt.reset();
  v.stats.presentMs.push_back(msBetween(presentStart, now));
  v.stats.frameMs.push_back(msBetween(v.frameStart, now));
  v.frameStart = now;
}

// Four times a second: reloads the scene if one of its files changed, and updates the title.
void pollAndTitle(Viewer& v, const RenderOptions& options) {
  const Clock::time_point now = Clock::now();
  if (now - v.lastTitle <= std::chrono::milliseconds(250)) return;
  const VkPhysicalDeviceLimits& device = v.renderer.device.properties.limits;
  reloadIfChanged(v.state, options.scene, readPolicyOf(options), v.fileTimes,
                  {v.pack, device.maxImageDimension2D, v.renderer.device.lavapipe, loopTraces(v.renderer.coverage)});
  const double frameMs = v.stats.frameMs.empty() ? 0.0 : v.stats.frameMs.back();
  const ViewerState& s = v.state;
  const std::string readout =
      s.magnifier ? pointReadout(s.scene, hitAt(s.scene, int(v.renderer.width), int(v.renderer.height), s.cursorX, s.cursorY),
                                 v.gpuScene.images)
                  : "";
  glfwSetWindowTitle(v.window.window, title(s, v.samples, v.target, frameMs, v.renderer.lastFrameMs, readout).c_str());
  v.lastTitle = now;
}

// The frame loop, until the window closes (or --frames frames are shown).
void runFrames(Viewer& v, const RenderOptions& options) {
  v.lastTitle = Clock::now() - std::chrono::seconds(1);
  v.frameStart = Clock::now();
  while (!glfwWindowShouldClose(v.window.window)) {
    waitForWork(v, options.frames != 0);
    const VkExtent2D size = framebufferSize(v.window);
    if (size.width == 0 || size.height == 0) {  // minimised
      glfwWaitEvents();
      continue;
    }
    updateScene(v, size);
    renderAndShow(v, options);
    if (options.frames && v.stats.frameMs.size() >= options.frames) break;
    pollAndTitle(v, options);
  }
  if (options.stats || options.frames) v.stats.print(v.renderer.width, v.renderer.height);
  if (v.renderer.device.validationErrors > 0)
    throw VulkanError(std::to_string(v.renderer.device.validationErrors) + " Vulkan validation error(s)");
}

void closeViewer(Viewer& v) {
  destroyBuffer(v.renderer.device, v.splitPixels);
  destroyWindow(v.window, v.renderer.device);
  destroyRenderer(v.renderer);
  shutdownWindowSystem();
}

}  // namespace

void runViewer(const RenderOptions& options) {
  Viewer v;
  loadScene(v, options);
  initWindowSystem();
  try {
    openViewer(v, options);
    runFrames(v, options);
  } catch (...) {
    closeViewer(v);
    throw;
  }
  closeViewer(v);
}
