#include "kernel_plan.h"

#include "scene_limits.h"
#include "tile_kernels.h"

namespace {

// The viewer's kind sets for `key` (none: the one kernel).
std::vector<TextureKinds> viewerTileSets(const Renderer& renderer, const KernelKey& key) {
  const TextureKinds all{key.shape.sphereKinds, key.shape.planeKinds};
  if (!renderer.device.lavapipe || !sphereFreeTilesSave(all)) return {};
  return sphereFreeTileKernels(all);
}

}  // namespace

bool samplesPerDispatch(const Renderer& renderer, const Scene& scene, const GpuScene& gpuScene, const RenderJob& job) {
  if (job.samplesPerPixel <= 1) return false;
  if (renderer.coverage) return true;
  const uint32_t traces = job.samplesPerPixel + (renderer.passMask != 0 ? 1 : 0);
  return renderer.device.lavapipe && (gpuScene.shape.sphereTree != SPHERE_TREE_NONE ||
                                      !withinLoopLimit(scene, traces));
}

void prepareFrameKernels(Renderer& renderer, const GpuScene& gpuScene, const KernelKey& key, double samples) {
  preparePipeline(renderer, key);
  if (!renderer.device.lavapipe || bandCount(renderer) != 1) return;
  const TilePlan plan = planTileKernels(gpuScene, {key.shape.sphereKinds, key.shape.planeKinds});
  if (tileKernelsPay(plan, samples)) prepareTileKernels(renderer, key, plan);
}

std::vector<KernelKey> viewerFrameKernels(const Renderer& renderer, const KernelKey& key) {
  const std::vector<TextureKinds> sets = viewerTileSets(renderer, key);
  if (sets.empty()) return {key};
  std::vector<KernelKey> keys;
  for (const TextureKinds& kinds : sets) keys.push_back(tileKernelKey(key, kinds));
  return keys;
}

void prepareViewerFrameKernels(Renderer& renderer, const GpuScene& packed, const KernelKey& key) {
  const std::vector<TextureKinds> sets = viewerTileSets(renderer, key);
  prepareTileKernels(renderer, key, sets.empty() ? TilePlan{} : assignTiles(sets, tileKinds(packed), packed.tiles.columns));
}
