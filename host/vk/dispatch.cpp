#include "renderer.h"

#include "bindings.h"
#include "common.h"
#include "renderer_parts.h"
#include "scene_limits.h"

#include <algorithm>
#include <bitset>
#include <chrono>
#include <string>

namespace {

// Throws LoopBudgetError if the last dispatch reported passing the loop budget (clearing it).
void checkLoopBudget(Renderer& r) {
  uint32_t* status = static_cast<uint32_t*>(r.status.data);
  if (!(status[0] & STATUS_LOOP_BUDGET)) return;
  status[0] = 0;
  throw LoopBudgetError("the scene needs more than " + std::to_string(kMaxLoopIterations) +
                        " loop passes (objects tested, boxes entered, lights, noise octaves, samples) for one "
                        "group of 8 pixels, more than the lavapipe driver runs: use fewer lights, objects or "
                        "samples per pixel, or another Vulkan device");
}

// A barrier from the compute shaders' writes before it to `access` at `stages` after it.
void computeBarrier(VkCommandBuffer cmd, VkAccessFlags access, VkPipelineStageFlags stages) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = access;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

// Before the main kernel of FILTER_COVERAGE: an empty edge list (an indirect dispatch of no
// workgroups), which the main kernel fills.
void clearEdgeList(Renderer& r, VkCommandBuffer cmd) {
  const uint32_t header[4] = {0, 1, 1, 0};
  vkCmdUpdateBuffer(cmd, r.edgeList.buffer, 0, sizeof(header), header);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
}

// After the main kernel of FILTER_COVERAGE: the edge pass shades the listed pixels again, one
// invocation each (an indirect dispatch).
void recordEdgePass(Renderer& r, VkCommandBuffer cmd) {
  computeBarrier(cmd, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT,
                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, r.edgePipeline);
  uint32_t noOffset = 0;
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipelineLayout, 0, 1, &r.descriptorSet, 1, &noOffset);
  vkCmdDispatchIndirect(cmd, r.edgeList.buffer, 0);
}

}  // namespace

// `tileOffset`: the dynamic offset of BINDING_TILE_ORDER (a tile kernel's tiles).
void bindAndDispatch(Renderer& r, VkCommandBuffer cmd, VkPipeline pipeline, uint32_t baseX, uint32_t groupsX,
                     uint32_t groupsY, uint32_t tileOffset) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipelineLayout, 0, 1, &r.descriptorSet, 1,
                          &tileOffset);
  vkCmdDispatchBase(cmd, baseX, 0, 0, groupsX, groupsY, 1);
}

uint32_t bandCount(const Renderer& r) { return (r.height + r.bandRows - 1) / r.bandRows; }

uint32_t bandHeight(const Renderer& r) { return std::min(r.bandRows, r.height - r.bandFirstRow); }

void selectBand(Renderer& r, uint32_t firstRow) {
  // Every earlier dispatch has completed (they all wait), so the mapped uniform can change.
  r.bandFirstRow = firstRow;
  gpu::Frame* frame = static_cast<gpu::Frame*>(r.frame.data);
  frame->rowOffset = firstRow;
  frame->bandRows = bandHeight(r);
}

void renderFrame(Renderer& r) {
  auto start = std::chrono::steady_clock::now();
  VkCommandBuffer cmd = beginCommands(r.device);
  if (r.timestamps) {
    vkCmdResetQueryPool(cmd, r.timestamps, 0, 2);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, r.timestamps, 0);
  }
  if (r.edgePipeline) clearEdgeList(r, cmd);
  if (r.tileDispatches.empty())
    bindAndDispatch(r, cmd, r.pipeline, 0, (r.width + WORKGROUP_X - 1) / WORKGROUP_X,
                    (bandHeight(r) + WORKGROUP_Y - 1) / WORKGROUP_Y);
  for (const TileDispatch& d : r.tileDispatches) bindAndDispatch(r, cmd, d.pipeline, 0, d.count, 1, d.offset);
  if (r.edgePipeline) recordEdgePass(r, cmd);
  if (r.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, r.timestamps, 1);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};  // the status word
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                       nullptr, 0, nullptr);
  submitAndWait(r.device, cmd);
  checkLoopBudget(r);
  cachedPipeline(r, r.pipelineKey).dispatched = true;
  for (const TileDispatch& d : r.tileDispatches) cachedPipeline(r, d.key).dispatched = true;
  if (r.edgePipeline) cachedPipeline(r, r.edgeKey).dispatched = true;
  r.lastFrameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  uint64_t ticks[2] = {0, 0};
  if (r.timestamps && vkGetQueryPoolResults(r.device.device, r.timestamps, 0, 2, sizeof(ticks), ticks,
                                            sizeof(uint64_t), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS)
    r.lastFrameMs = double(ticks[1] - ticks[0]) * r.device.properties.limits.timestampPeriod * 1e-6;
}

uint32_t edgePixelCount(const Renderer& r) {
  // The list's header (clearEdgeList), written by the main kernel; renderFrame's barrier makes it visible.
  return r.edgePipeline && r.edgeList.data ? static_cast<const uint32_t*>(r.edgeList.data)[3] : 0;
}

void renderSample(Renderer& r, uint32_t index) {
  // The previous dispatch has completed (renderFrame waits), so the mapped uniform can change.
  gpu::Frame* frame = static_cast<gpu::Frame*>(r.frame.data);
  frame->sampleIndex = index;
  frame->sampleWeight = 1.0f / float(index + 1);
  r.sampleWeight = frame->sampleWeight;
  frame->displayBgra = r.displayBgra;
  renderFrame(r);
}

void readbackFrame(Renderer& r) {
  // The kernel's writes (an earlier, completed submission) become visible to the host.
  VkCommandBuffer cmd = beginCommands(r.device);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
  submitAndWait(r.device, cmd);
  if (r.pipelineKey.progressive) {
    // The progressive kernel writes no float image (trace.comp.glsl): the mean is the running
    // sum times the last sample's weight, the kernel's own float multiply.
    const float* sums = static_cast<const float*>(r.accumulation.data);
    float* means = static_cast<float*>(r.pixels.data);
    for (size_t i = 0; i < size_t(r.width) * bandHeight(r); ++i) {
      for (size_t c = 0; c < 3; ++c) means[4 * i + c] = sums[4 * i + c] * r.sampleWeight;
      means[4 * i + 3] = 1.0f;
    }
  }
}

const float* framePixels(const Renderer& r) { return static_cast<const float*>(r.pixels.data); }

const float* passPixels(const Renderer& r, Pass pass) {
  const uint32_t bit = uint32_t(pass);
  if (!(r.passMask >> bit & 1u)) return nullptr;
  const uint32_t plane = uint32_t(std::bitset<AOV_COUNT>(r.passMask & ((1u << bit) - 1u)).count());
  return static_cast<const float*>(r.passes.data) + size_t(plane) * r.width * bandHeight(r) * 4;
}

void swapAccumulation(Renderer& r) {
  std::swap(r.accumulation, r.otherAccumulation);
  std::swap(r.display, r.otherDisplay);
  writeTraceDescriptors(r);
}
