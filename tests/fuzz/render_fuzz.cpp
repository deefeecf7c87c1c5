// libFuzzer target: scene text, as if it were a file in scenes/ (as parser_fuzz.cpp takes it),
// rendered when it parses at 8 x 8 pixels and 1 sample with both texture filters (point and box)
// on one Vulkan device created once. Every pixel of the float output must be finite: a
// non-finite value (a NaN or infinity written as black) aborts. The pipelines are the
// unspecialised kernels (every texture kind, counts from Frame, values from the uniform buffers),
// each created once, so an input costs dispatches and no compilation: the loop over every sphere
// (where the spheres fit the uniform block) and the sphere tree's kernel, which every scene with a
// sphere also renders through (a tree over a few spheres is as valid as over many): primary rays
// through the tile's list, shadow rays through the cell's and light's lists where the scene has
// them (shadow_lists.h), the tree where a list is long. Scenes that
// buildGpuScene refuses (over the kernel's limits, an image that does not load) and renders over
// lavapipe's loop budget are skipped. Built by RAYTEX_FUZZ_RENDER=ON with clang;
// tests/fuzz/run.sh render builds and runs it.
#include "gpu_scene.h"
#include "parser.h"
#include "renderer.h"
#include "shadow_lists.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

constexpr uint32_t kSize = 8;

Renderer& sharedRenderer() {
  static Renderer* renderer = [] {
    auto* r = new Renderer;  // never destroyed: the process ends with the fuzzer
    createRenderer(*r, {-1, false});
    return r;
  }();
  return *renderer;
}

// The scene packed to walk a sphere tree, whatever its number of spheres: with `lists`, primary
// rays through tile lists and, where they fit, shadow rays through shadow lists; else every ray
// walks the tree.
GpuScene withTree(GpuScene g, const Scene& scene, bool lists) {
  if (scene.spheres.empty()) return g;
  if (g.shape.sphereTree == SPHERE_TREE_NONE) {
    g.shape.sphereTree = SPHERE_TREE_UNIFORM;
    g.sphereTree = buildSphereBvh(scene.spheres);
  }
  g.shape.tileLists = lists;
  g.shape.shadowLists = lists && shadowListsFit(scene.lights.size(), scene.planes.size());
  packCamera(g, scene, kSize, kSize);
  return g;
}

// Renders the uploaded scene with `filter` and the scene's way of walking its spheres; aborts on
// the first non-finite channel.
void renderFinite(Renderer& renderer, const SceneShape& shape, uint32_t filter, const std::string& text) {
  KernelKey key;  // the unspecialised kernel: every kind, counts read at run time
  key.shape.sphereTree = shape.sphereTree;
  key.shape.tileLists = shape.tileLists;
  key.shape.shadowLists = shape.shadowLists;
  key.textureFilter = filter;
  preparePipeline(renderer, key);
  renderFrame(renderer);
  readbackFrame(renderer);
  const float* pixels = framePixels(renderer);
  for (size_t i = 0; i < size_t(kSize) * kSize * 4; ++i) {
    if (!std::isfinite(pixels[i])) {
      fprintf(stderr, "non-finite value %g in channel %zu of pixel (%zu, %zu), filter %s, scene:\n%s\n",
              double(pixels[i]), i % 4, i / 4 % kSize, i / 4 / kSize, filter == FILTER_BOX ? "box" : "point",
              text.c_str());
      abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = std::string(RAYTEX_SOURCE_DIR) + "/scenes/fuzz.cfg";
  const std::string text(reinterpret_cast<const char*>(data), size);
  Scene scene;
  GpuScene gpuScene;
  try {
    scene = parseSceneText(text, path);
    gpuScene = buildGpuScene(scene, kSize, kSize);
  } catch (const SceneError&) {
    return 0;  // not a scene raytex renders: parser_fuzz.cpp checks the messages
  } catch (const ImageInputError&) {
    return 0;  // an image raytex does not load: likewise
  }
  Renderer& renderer = sharedRenderer();
  try {
    for (const GpuScene& g : {gpuScene, withTree(gpuScene, scene, false), withTree(gpuScene, scene, true)}) {
      uploadScene(renderer, g);
      renderFinite(renderer, g.shape, FILTER_POINT, text);
      renderFinite(renderer, g.shape, FILTER_BOX, text);
    }
  } catch (const LoopBudgetError&) {
    return 0;  // reported by raytex (exit 1), the image not used
  }
  return 0;
}
