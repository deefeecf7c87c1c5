#include "renderer.h"

#include "bindings.h"
#include "common.h"
#include "pipeline.h"
#include "renderer_parts.h"
#include "scene_limits.h"

#include <algorithm>
#include <vector>

namespace {

// The key with the device's loop budget (lavapipe's limit, none elsewhere) and the passes the
// pass buffer holds.
KernelKey budgeted(const Renderer& r, KernelKey key) {
  key.loopBudget = r.device.lavapipe ? uint32_t(kMaxLoopIterations) : 0u;
  key.passMask = r.passMask;
  return key;
}

// The plan's tiles laid out for the dispatches: word 0 TILE_ORDER_NONE, then each kernel's
// tiles in blocks of at most TILE_ORDER_CHUNK, each from an offset the device can bind.
std::vector<uint32_t> layOutTiles(const Renderer& r, const TilePlan& plan, std::vector<TileDispatch>& dispatches) {
  const uint32_t align = uint32_t(std::max<VkDeviceSize>(r.device.properties.limits.minUniformBufferOffsetAlignment, 4) / 4);
  std::vector<uint32_t> words{TILE_ORDER_NONE};
  dispatches.clear();
  for (const TileKernel& k : plan.kernels)
    for (size_t first = 0; first < k.tiles.size(); first += TILE_ORDER_CHUNK) {
      words.resize((words.size() + align - 1) / align * align, TILE_ORDER_NONE);
      const size_t count = std::min<size_t>(TILE_ORDER_CHUNK, k.tiles.size() - first);
      dispatches.push_back({{}, VK_NULL_HANDLE, uint32_t(4 * words.size()), uint32_t(count)});
      words.insert(words.end(), k.tiles.begin() + ptrdiff_t(first), k.tiles.begin() + ptrdiff_t(first + count));
    }
  return words;
}

// The edge pass of FILTER_COVERAGE's `key` (its main kernel's, or the tile kernels' base key),
// or none for the other filters.
KernelKey edgePassKey(const KernelKey& key) {
  KernelKey edge = key;
  edge.edgePass = 1;
  edge.tileOrder = 0;
  return edge;
}

void prepareEdgePass(Renderer& r, const KernelKey& key) {
  r.edgePipeline = VK_NULL_HANDLE;
  if (key.textureFilter != FILTER_COVERAGE) return;
  const CachedPipeline& p = cachedPipeline(r, edgePassKey(key));
  r.edgePipeline = p.pipeline;
  r.edgeKey = p.key;
}

}  // namespace

CachedPipeline& cachedPipeline(Renderer& r, const KernelKey& unbudgeted) {
  const KernelKey key = budgeted(r, unbudgeted);
  for (CachedPipeline& p : r.pipelines)
    if (p.key == key) return p;
  r.pipelines.push_back({key, createTracePipeline(r.device, r.pipelineLayout, key), false});
  return r.pipelines.back();
}

// Writes the tile kernels' words (`words` from offset 0), replacing the buffer when they do not
// fit. Every dispatch's block of TILE_ORDER_CHUNK words lies within the buffer.
void writeTileOrder(Renderer& r, const std::vector<uint32_t>& words) {
  const VkDeviceSize bytes = 4 * (words.size() + TILE_ORDER_CHUNK);
  if (r.tileOrder.size < bytes) {
    destroyBuffer(r.device, r.tileOrder);
    r.tileOrder = createBuffer(r.device, bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (r.descriptorSet) writeTraceDescriptors(r);
  }
  writeBuffer(r.tileOrder, words.data(), 4 * words.size());
  r.tileOrderWords = words;
}

void preparePipeline(Renderer& r, const KernelKey& key) {
  r.tileDispatches.clear();
  prepareEdgePass(r, key);
  if (r.pipeline && r.pipelineKey == budgeted(r, key)) return;
  r.pipeline = cachedPipeline(r, key).pipeline;
  r.pipelineKey = budgeted(r, key);
}

void prepareTileKernels(Renderer& r, const KernelKey& key, const TilePlan& plan) {
  if (plan.kernels.empty()) return preparePipeline(r, key);
  prepareEdgePass(r, key);
  std::vector<TileDispatch> dispatches;
  const std::vector<uint32_t> words = layOutTiles(r, plan, dispatches);
  if (words != r.tileOrderWords) {
    VK_CHECK(vkDeviceWaitIdle(r.device.device));
    writeTileOrder(r, words);
  }
  size_t d = 0;
  for (const TileKernel& k : plan.kernels) {
    const CachedPipeline& p = cachedPipeline(r, tileKernelKey(key, k.kinds));
    for (size_t n = 0; n < (k.tiles.size() + TILE_ORDER_CHUNK - 1) / TILE_ORDER_CHUNK; ++n, ++d) {
      dispatches[d].key = p.key;
      dispatches[d].pipeline = p.pipeline;
    }
  }
  r.tileDispatches = std::move(dispatches);
  r.pipeline = r.tileDispatches[0].pipeline;
  r.pipelineKey = r.tileDispatches[0].key;
}

bool pipelineWarm(const Renderer& r, const KernelKey& key) {
  if (key.textureFilter == FILTER_COVERAGE && !key.edgePass && !pipelineWarm(r, edgePassKey(key))) return false;
  for (const CachedPipeline& p : r.pipelines)
    if (p.key == budgeted(r, key)) return p.dispatched;
  return false;
}

void warmPipeline(Renderer& r, const KernelKey& key) {
  if (key.textureFilter == FILTER_COVERAGE && !key.edgePass) warmPipeline(r, edgePassKey(key));
  CachedPipeline& p = cachedPipeline(r, key);
  if (p.dispatched) return;
  // One workgroup past the image's right edge (a tile kernel's: tile TILE_ORDER_NONE; the edge
  // pass's: past its list's end): nothing is written, but lavapipe compiles the kernel for the
  // bound resources.
  const uint32_t past = p.key.edgePass ? uint32_t(r.width) * r.bandRows / EDGE_GROUP_SIZE + 1
                        : p.key.tileOrder ? 0
                                          : (r.width + WORKGROUP_X - 1) / WORKGROUP_X;
  VkCommandBuffer cmd = beginCommands(r.device);
  bindAndDispatch(r, cmd, p.pipeline, past, 1, 1, 0);
  submitAndWait(r.device, cmd);
  p.dispatched = true;
}
