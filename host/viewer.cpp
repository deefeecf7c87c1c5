#include "viewer.h"

#include "gpu_scene.h"
#include "image_io.h"
#include "parser.h"
#include "renderer.h"
#include "window.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

// The course's materials, in the order of the notes; keys 1-8 put them on the sphere.
const char* const kCourseMaterials[] = {"aSolidChecker", "aNoise",      "aMarble",      "aWood",
                                        "anImage",       "aTurbulence", "aDturbulence", "aChecker"};

struct ViewerState {
  Scene scene;
  bool dirty = true;         // the GPU scene must be rebuilt
  bool screenshot = false;   // write the next frame to the output PNG
  int planeMaterial = -1;    // index into kCourseMaterials for P cycling
  std::string message;      // shown in the title (e.g. a material the scene does not define)
};

int materialIndex(const Scene& scene, const char* name) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return int(i);
  return -1;
}

std::string materialName(const Scene& scene, int index) {
  return index < 0 ? std::string("default") : scene.materials[size_t(index)].name;
}

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  auto* state = static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
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
    state->dirty = true;
  } else if (key == GLFW_KEY_S) {
    state->screenshot = true;
  } else if (key == GLFW_KEY_P) {
    // The next course material the scene defines.
    for (int step = 1; step <= 8; ++step) {
      int next = (state->planeMaterial + step + 8) % 8;
      int index = materialIndex(state->scene, kCourseMaterials[next]);
      if (index < 0) continue;
      state->planeMaterial = next;
      for (Plane& p : state->scene.planes) p.material = index;
      state->dirty = true;
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

// Re-parses the scene when one of its files changed. A parse error is printed with its
// file:line:col and the last good scene stays.
void reloadIfChanged(ViewerState& state, const std::string& path,
                     std::vector<std::filesystem::file_time_type>& times) {
  std::vector<std::filesystem::file_time_type> now = fileTimes(state.scene);
  if (now == times) return;
  times = now;
  try {
    Scene scene = parseSceneFile(path);
    times = fileTimes(scene);
    state.scene = std::move(scene);
    state.dirty = true;
    state.message = "reloaded";
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    state.message = "scene error, see the terminal";
  }
}

std::string title(const ViewerState& state, double frameMs) {
  std::string t = "raytex";
  if (!state.scene.spheres.empty()) t += " | sphere: " + materialName(state.scene, state.scene.spheres[0].material);
  if (!state.scene.planes.empty()) t += " | plane: " + materialName(state.scene, state.scene.planes[0].material);
  char ms[32];
  snprintf(ms, sizeof(ms), " | %.1f ms/frame", frameMs);
  t += ms;
  if (!state.message.empty()) t += " | " + state.message;
  return t;
}

}  // namespace

int runViewer(const RenderOptions& options) {
  ViewerState state;
  try {
    state.scene = parseSceneFile(options.scene);
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  std::string error;
  if (!initWindowSystem(&error)) {
    fprintf(stderr, "raytex: %s\n", error.c_str());
    return 1;
  }
  for (size_t i = 0; i < 8 && !state.scene.planes.empty(); ++i)
    if (materialIndex(state.scene, kCourseMaterials[i]) == state.scene.planes[0].material) state.planeMaterial = int(i);

  Window window;
  Renderer renderer;
  int rc = 0;
  try {
    int width = int(options.width.value_or(uint32_t(state.scene.render.width.value_or(640))));
    int height = int(options.height.value_or(uint32_t(state.scene.render.height.value_or(480))));
    window.window = openWindow(width, height, "raytex");
    glfwSetWindowUserPointer(window.window, &state);
    glfwSetKeyCallback(window.window, onKey);
    DeviceOptions deviceOptions;
    deviceOptions.deviceIndex = options.device;
    deviceOptions.validation = options.validate;
    deviceOptions.instanceExtensions = windowInstanceExtensions();
    deviceOptions.presentSupport = windowPresentSupport;
    createRenderer(renderer, deviceOptions);
    createSwapchain(window, renderer.device);

    uint32_t textureKinds = 0;
    auto lastTitle = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    std::vector<std::filesystem::file_time_type> times = fileTimes(state.scene);
    while (!glfwWindowShouldClose(window.window)) {
      glfwPollEvents();
      VkExtent2D size = framebufferSize(window);
      if (size.width == 0 || size.height == 0) {  // minimised
        glfwWaitEvents();
        continue;
      }
      if (size.width != renderer.width || size.height != renderer.height) state.dirty = true;
      if (state.dirty) {
        GpuScene g = buildGpuScene(state.scene, size.width, size.height);
        uploadScene(renderer, g);
        textureKinds = g.textureKinds;
        state.dirty = false;
      }
      preparePipeline(renderer, {textureKinds, OUTPUT_SHADED, FILTER_POINT, 1});
      renderFrame(renderer);
      if (state.screenshot) {
        // The same readback and encoding as raytex render: the same PNG for the same view.
        state.screenshot = false;
        readbackFrame(renderer);
        writePngAtomic(options.output, encodeSrgb(framePixels(renderer), int(renderer.width), int(renderer.height)));
        state.message = "wrote " + options.output;
        printf("raytex: wrote %s (%ux%u)\n", options.output.c_str(), renderer.width, renderer.height);
        fflush(stdout);
      }
      if (!presentImage(window, renderer.device, renderer.output)) createSwapchain(window, renderer.device);
      auto now = std::chrono::steady_clock::now();
      if (now - lastTitle > std::chrono::milliseconds(250)) {  // also the reload poll
        reloadIfChanged(state, options.scene, times);
        glfwSetWindowTitle(window.window, title(state, renderer.lastFrameMs).c_str());
        lastTitle = now;
      }
    }
    if (renderer.device.validationErrors > 0) {
      fprintf(stderr, "raytex: %d Vulkan validation error(s)\n", renderer.device.validationErrors);
      rc = 1;
    }
  } catch (const SceneError& e) {
    fprintf(stderr, "%s\n", e.what());
    rc = 2;
  } catch (const std::exception& e) {
    fprintf(stderr, "raytex: %s\n", e.what());
    rc = 1;
  }
  destroyWindow(window, renderer.device);
  destroyRenderer(renderer);
  shutdownWindowSystem();
  return rc;
}
