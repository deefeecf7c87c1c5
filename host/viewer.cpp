#include "viewer.h"

#include "scene_limits.h"

#include "gpu_scene.h"
#include "image_io.h"
#include "median.h"
#include "output_file.h"
#include "parser.h"
#include "render_output.h"
#include "scene_notes.h"
#include "renderer.h"
#include "window.h"

#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

// The course's materials, in the order of the notes; keys 1-8 put them on the sphere.
const char* const kCourseMaterials[] = {"aSolidChecker", "aNoise",      "aMarble",      "aWood",
                                        "anImage",       "aTurbulence", "aDturbulence", "aChecker"};

// The camera orbits its lookat point about the scene's up axis: eye = lookat + radius *
// (cos(elevation) (cos(azimuth) e1 + sin(azimuth) e2) + sin(elevation) up).
struct Orbit {
  Camera home;               // the scene file's camera (R returns to it)
  glm::dvec3 up{0, 1, 0}, e1{1, 0, 0}, e2{0, 0, 1};
  double radius = 1.0, azimuth = 0.0, elevation = 0.0;
};

Orbit orbitOf(const Camera& camera) {
  Orbit o;
  o.home = camera;
  o.up = glm::normalize(camera.up);
  glm::dvec3 offset = camera.eye - camera.lookat;
  o.radius = glm::length(offset);
  glm::dvec3 dir = offset / o.radius;
  o.elevation = std::asin(std::clamp(glm::dot(dir, o.up), -1.0, 1.0));
  glm::dvec3 flat = dir - o.up * glm::dot(dir, o.up);
  // The parser rejects an up parallel to the view; fall back to any perpendicular axis.
  o.e1 = glm::length(flat) > 1e-9 ? glm::normalize(flat) : glm::normalize(glm::cross(o.up, glm::dvec3(1, 0, 0)));
  o.e2 = glm::cross(o.up, o.e1);
  return o;
}

using Clock = std::chrono::steady_clock;

struct ViewerState {
  Scene scene;
  Orbit orbit;
  bool dirty = true;         // the GPU scene must be rebuilt (size or scene file changed)
  bool cameraMoved = false;  // the camera or an object's material changed: re-pack the objects
  bool dragging = false;
  double lastX = 0.0, lastY = 0.0;
  bool screenshot = false;   // write the image to the output PNG once it has every sample
  bool refresh = false;      // the window needs the image again (exposed)
  int planeMaterial = -1;    // index into kCourseMaterials for P cycling
  std::string message;      // shown in the title (e.g. a material the scene does not define)
  std::optional<Clock::time_point> switchedAt;  // a material key, until its frame is shown
  std::optional<GpuScene> reloaded;  // a reloaded scene's GPU data, its images checked and decoded
};

// How the viewer packs a scene, and what a reloaded scene's images must pass before it replaces
// the scene on screen.
struct ImageLimits {
  PackOptions pack;  // every material (a key switches to it), mip chains for the filtered kernel
  uint32_t maxImageDimension2D = 0;  // the device's
  bool lavapipe = false;  // its driver's loop limit applies (scene_limits.h)
  uint32_t traces = 1;    // checkLoopLimit's: loopTraces
};

int materialIndex(const Scene& scene, const char* name) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return int(i);
  return -1;
}

std::string materialName(const Scene& scene, int index) {
  return index < 0 ? std::string("default") : scene.materials[size_t(index)].name;
}

// Moves the camera by angles (radians) and a zoom factor, elevation kept off the poles.
void moveCamera(ViewerState& state, double dAzimuth, double dElevation, double zoom) {
  Orbit& o = state.orbit;
  o.azimuth += dAzimuth;
  o.elevation = std::clamp(o.elevation + dElevation, -1.55, 1.55);
  o.radius = std::clamp(o.radius * zoom, 1e-3, 1e7);
  glm::dvec3 dir = std::cos(o.elevation) * (std::cos(o.azimuth) * o.e1 + std::sin(o.azimuth) * o.e2) +
                   std::sin(o.elevation) * o.up;
  state.scene.camera.eye = state.scene.camera.lookat + o.radius * dir;
  state.cameraMoved = true;
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
  auto* state = static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  state->dragging = action == GLFW_PRESS;
  glfwGetCursorPos(window, &state->lastX, &state->lastY);
}

void onCursor(GLFWwindow* window, double x, double y) {
  auto* state = static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
  if (state->dragging) moveCamera(*state, -(x - state->lastX) * 0.01, (y - state->lastY) * 0.01, 1.0);
  state->lastX = x;
  state->lastY = y;
}

void onScroll(GLFWwindow* window, double, double yOffset) {
  moveCamera(*static_cast<ViewerState*>(glfwGetWindowUserPointer(window)), 0.0, 0.0, std::pow(0.9, yOffset));
}

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  auto* state = static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
  const double step = 5.0 * 3.14159265358979 / 180.0;
  if (key == GLFW_KEY_LEFT || key == GLFW_KEY_A) {
    moveCamera(*state, -step, 0.0, 1.0);
  } else if (key == GLFW_KEY_RIGHT || key == GLFW_KEY_D) {
    moveCamera(*state, step, 0.0, 1.0);
  } else if (key == GLFW_KEY_UP || key == GLFW_KEY_W) {
    moveCamera(*state, 0.0, step, 1.0);
  } else if (key == GLFW_KEY_DOWN || key == GLFW_KEY_S) {
    moveCamera(*state, 0.0, -step, 1.0);
  } else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD || key == GLFW_KEY_PAGE_UP) {
    moveCamera(*state, 0.0, 0.0, 0.9);
  } else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT || key == GLFW_KEY_PAGE_DOWN) {
    moveCamera(*state, 0.0, 0.0, 1.0 / 0.9);
  } else if (key == GLFW_KEY_R) {
    state->scene.camera = state->orbit.home;
    state->orbit = orbitOf(state->orbit.home);
    state->cameraMoved = true;
  }
  if (action != GLFW_PRESS) return;  // the rest do not repeat
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) {
    glfwSetWindowShouldClose(window, GLFW_TRUE);
  } else if (key >= GLFW_KEY_1 && key <= GLFW_KEY_8) {
    const char* name = kCourseMaterials[key - GLFW_KEY_1];
    int index = materialIndex(state->scene, name);
    if (index < 0) {
      state->message = std::string(name) + " is not defined by this scene";
      return;
    }
    for (Sphere& s : state->scene.spheres) s.material = index;
    state->message.clear();
    state->cameraMoved = true;
    state->switchedAt = Clock::now();
  } else if (key == GLFW_KEY_F12) {
    state->screenshot = true;
  } else if (key == GLFW_KEY_P) {
    // The next course material the scene defines.
    for (int step = 1; step <= 8; ++step) {
      int next = (state->planeMaterial + step + 8) % 8;
      int index = materialIndex(state->scene, kCourseMaterials[next]);
      if (index < 0) continue;
      state->planeMaterial = next;
      for (Plane& p : state->scene.planes) p.material = index;
      state->cameraMoved = true;
      state->switchedAt = Clock::now();
      break;
    }
  }
}

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
// error with its file:line:col, an image refused or over the device's limits) is printed and
// the last good scene stays.
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
    state.scene = std::move(scene);
    state.reloaded = std::move(gpuScene);
    state.orbit = orbitOf(state.scene.camera);
    state.dirty = true;
    state.message = "reloaded";
  } catch (const Error& e) {
    fprintf(stderr, "%s\n", errorLine(e).c_str());
    state.message = "scene error, see the terminal";
  }
}

// Samples per pixel the viewer accumulates when neither --spp nor the scene's render block
// says: 8 x 8, about a second at 60 frames per second.
constexpr uint32_t kViewerSamplesPerPixel = 64;

// F12: the image on screen, every sample in, written to options.output (the file raytex render
// writes for this view, its format and metadata included). An output that is one of the scene's
// files now (a reload may have added it) or a failed write is one line on stderr and in the
// title; the viewer goes on.
void saveScreenshot(ViewerState& state, Renderer& renderer, const RenderOptions& options, const RenderJob& job,
                    const char* settings) {
  const std::string& output = options.output;
  std::string error = outputClash(output, state.scene);
  if (error.empty()) {
    readbackFrame(renderer);
    try {
      ImageOutput file(renderOutputSpec(options, job, renderMetadata(options, job, {})));
      file.writeBand(0, int(renderer.height), framePixels(renderer), {});
      file.finish();
    } catch (const Error& e) {
      error = e.what();
    }
  }
  if (!error.empty()) {
    fprintf(stderr, "raytex: %s\n", error.c_str());
    state.message = "not saved, see the terminal";
    return;
  }
  state.message = "wrote " + output;
  printf("raytex: wrote %s (%ux%u, %s)\n", output.c_str(), renderer.width, renderer.height, settings);
  fflush(stdout);
}

std::string title(const ViewerState& state, uint32_t samples, uint32_t target, double frameMs, double gpuMs) {
  std::string t = "raytex";
  if (!state.scene.spheres.empty()) t += " | sphere: " + materialName(state.scene, state.scene.spheres[0].material);
  if (!state.scene.planes.empty()) t += " | plane: " + materialName(state.scene, state.scene.planes[0].material);
  char text[96];
  snprintf(text, sizeof(text), " | %u/%u samples | %.1f ms/frame (GPU %.1f)", samples, target, frameMs, gpuMs);
  t += text;
  if (!state.message.empty()) t += " | " + state.message;
  return t;
}

// The pipeline that renders `scene` (its objects' materials as switched) progressively with the
// job's settings. Every material is packed, so an object's image may be any of the packed
// scene's elements of BINDING_IMAGES.
KernelKey viewerKey(const GpuScene& packed, const Scene& scene, const RenderJob& job) {
  KernelOptions options;
  options.textureFilter = kernelFilter(job.filter);
  options.imageFilter = kernelImageFilter(job.imageFilter);
  options.samplesPerSide = job.samplesPerSide;
  options.progressive = true;
  KernelKey key = kernelKey(packed, options);
  key.shape = sceneShape(scene);
  if (key.shape.imageCount > 0) key.shape.imageCount = uint32_t(packed.images.size());
  return key;
}

// The kinds of the viewer's tile kernels for `key` (tile_kernels.h): on lavapipe, where a tile
// no sphere reaches saves (sphereFreeTilesSave), the planes' kinds alone and all, whatever the
// camera, so a camera move never needs another kernel. None (the one kernel) elsewhere.
std::vector<TextureKinds> viewerTileSets(const Renderer& renderer, const KernelKey& key) {
  const TextureKinds all{key.shape.sphereKinds, key.shape.planeKinds};
  if (!renderer.device.lavapipe || !sphereFreeTilesSave(all)) return {};
  return sphereFreeTileKernels(all);
}

// The kernels of the frames of `scene`.
std::vector<KernelKey> viewerKernels(const Renderer& renderer, const GpuScene& packed, const Scene& scene,
                                     const RenderJob& job) {
  const KernelKey key = viewerKey(packed, scene, job);
  const std::vector<TextureKinds> sets = viewerTileSets(renderer, key);
  if (sets.empty()) return {key};
  std::vector<KernelKey> keys;
  for (const TextureKinds& kinds : sets) keys.push_back(tileKernelKey(key, kinds));
  return keys;
}

// Makes viewerKernels' kernels current, over their tiles for the camera as packed: after every
// pack, the only times the key or the tiles change.
void prepareViewerKernels(Renderer& renderer, const GpuScene& packed, const Scene& scene, const RenderJob& job) {
  const KernelKey key = viewerKey(packed, scene, job);
  const std::vector<TextureKinds> sets = viewerTileSets(renderer, key);
  prepareTileKernels(renderer, key, sets.empty() ? TilePlan{} : assignTiles(sets, tileKinds(packed), packed.tiles.columns));
}

// A pipeline a key could need next that has not run yet: the course materials on the sphere,
// then on the plane. False when all are ready.
bool nextPipelineToWarm(const ViewerState& state, const Renderer& renderer, const RenderJob& job,
                        const GpuScene& packed, KernelKey* key) {
  for (int onPlane = 0; onPlane < 2; ++onPlane)
    for (const char* name : kCourseMaterials) {
      int index = materialIndex(state.scene, name);
      if (index < 0) continue;
      Scene switched = state.scene;
      if (onPlane)
        for (Plane& p : switched.planes) p.material = index;
      else
        for (Sphere& s : switched.spheres) s.material = index;
      for (const KernelKey& k : viewerKernels(renderer, packed, switched, job))
        if (!pipelineWarm(renderer, k)) {
          *key = k;
          return true;
        }
    }
  return false;
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
  std::vector<std::filesystem::file_time_type> fileTimes;
  Clock::time_point lastTitle, frameStart;
};

// The scene, the job and how to pack it: bad input fails before any window opens.
void loadScene(Viewer& v, const RenderOptions& options) {
  ViewerState& state = v.state;
  state.scene = parseSceneFile(options.scene, ReadPolicy{options.allowRead});
  printSceneNotes(state.scene, stderr);
  checkOutput(options.output, state.scene);  // F12 writes -o
  v.job = resolveJob(options, state.scene.render, kViewerSamplesPerPixel);
  v.target = v.job.samplesPerSide * v.job.samplesPerSide;
  v.pack.mipmaps = v.job.filter != TextureFilter::Point;  // mip chains only for the filtered kernel
  v.pack.allMaterials = true;
  v.pack.maxImageMiB = options.maxImageMiB;
  state.orbit = orbitOf(state.scene.camera);
  for (size_t i = 0; i < 8 && !state.scene.planes.empty(); ++i)
    if (materialIndex(state.scene, kCourseMaterials[i]) == state.scene.planes[0].material) state.planeMaterial = int(i);
  v.fileTimes = fileTimes(state.scene);
}

// The window with its input callbacks, the device that presents to it, and its swapchain.
void openViewer(Viewer& v, const RenderOptions& options) {
  v.window.window = openWindow(int(v.job.width), int(v.job.height), "raytex");
  GLFWwindow* w = v.window.window;
  glfwSetWindowUserPointer(w, &v.state);
  glfwSetKeyCallback(w, onKey);
  glfwSetMouseButtonCallback(w, onMouseButton);
  glfwSetCursorPosCallback(w, onCursor);
  glfwSetScrollCallback(w, onScroll);
  glfwSetWindowRefreshCallback(w, [](GLFWwindow* window) {
    static_cast<ViewerState*>(glfwGetWindowUserPointer(window))->refresh = true;
  });
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

// Handles input; waits when there is nothing to render, compiling meanwhile what a key may need
// next so that the switch shows on the next frame.
void waitForWork(Viewer& v, bool keepRendering) {
  const ViewerState& s = v.state;
  const bool busy = v.samples < v.target || s.dirty || s.cameraMoved || s.refresh || s.screenshot;
  KernelKey warm;
  if (busy || keepRendering) {
    glfwPollEvents();
  } else if (nextPipelineToWarm(s, v.renderer, v.job, v.gpuScene, &warm)) {
    warmPipeline(v.renderer, warm);
    glfwPollEvents();
  } else {
    glfwWaitEventsTimeout(0.25);  // wakes for the reload poll
  }
}

// Re-packs and uploads what changed: everything for a new size, scene file or unpacked
// material; camera-relative positions and material indices for a camera move or a key.
void updateScene(Viewer& v, VkExtent2D size) {
  ViewerState& state = v.state;
  // Images are decoded only with the scene (start, reload) or when an object's material is not
  // packed (over MAX_MATERIALS); a new size re-packs the camera alone.
  bool unpacked = false;
  for (const Sphere& o : state.scene.spheres) unpacked = unpacked || !v.gpuScene.materialIndex.count(o.material);
  for (const Plane& o : state.scene.planes) unpacked = unpacked || !v.gpuScene.materialIndex.count(o.material);
  if (size.width != v.renderer.width || size.height != v.renderer.height || unpacked) state.dirty = true;
  if (!state.dirty && !state.cameraMoved) return;
  if (state.dirty && state.reloaded) {
    v.gpuScene = std::move(*state.reloaded);
    state.reloaded.reset();
  } else if (state.dirty && unpacked) {
    v.gpuScene = buildGpuScene(state.scene, size.width, size.height, v.pack);
  }
  packCamera(v.gpuScene, state.scene, size.width, size.height);
  if (state.dirty)
    uploadScene(v.renderer, v.gpuScene);
  else
    updateSceneBuffers(v.renderer, v.gpuScene);
  prepareViewerKernels(v.renderer, v.gpuScene, state.scene, v.job);
  state.dirty = state.cameraMoved = false;
  v.samples = 0;
}

// Adds a sample while the image lacks some, writes the F12 screenshot once it has all, and
// presents the image when it changed or the window was exposed.
void renderAndShow(Viewer& v, const RenderOptions& options) {
  ViewerState& state = v.state;
  if (options.frames && v.samples == v.target) v.samples = 0;  // --frames: keep rendering
  const bool render = v.samples < v.target;
  if (render) {
    renderSample(v.renderer, v.samples++);
    v.stats.gpuMs.push_back(v.renderer.lastFrameMs);
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
  if (!presentPixels(v.window, v.renderer.device, v.renderer.display)) {
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
  reloadIfChanged(v.state, options.scene, ReadPolicy{options.allowRead}, v.fileTimes,
                  {v.pack, device.maxImageDimension2D, v.renderer.device.lavapipe, loopTraces(v.renderer.coverage)});
  const double frameMs = v.stats.frameMs.empty() ? 0.0 : v.stats.frameMs.back();
  glfwSetWindowTitle(v.window.window, title(v.state, v.samples, v.target, frameMs, v.renderer.lastFrameMs).c_str());
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
