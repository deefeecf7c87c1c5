#include "renderer.h"

#include "common.h"
#include "renderer_parts.h"

#include <algorithm>
#include <bitset>
#include <string>

namespace {

// Progressive sums, one vec4 per pixel; a placeholder when not accumulating (the binding exists).
VkDeviceSize accumulationBytes(const Renderer& r, uint32_t width, uint32_t height) {
  return r.accumulate ? VkDeviceSize(width) * height * 16 : 16;
}

// Planes of the pass buffer (BINDING_AOV): one per requested pass.
uint32_t passPlanes(const Renderer& r) { return uint32_t(std::bitset<AOV_COUNT>(r.passMask).count()); }

// The coverage filter's list for bands of `rows` rows: its header and an entry per pixel at
// most; a placeholder without.
VkDeviceSize edgeListBytes(const Renderer& r, uint32_t width, uint32_t rows) {
  return r.coverage ? 16 + VkDeviceSize(width) * rows * 8 : 16;
}

// The pass buffer for bands of `rows` rows; a placeholder without passes (the binding exists).
VkDeviceSize passBytes(const Renderer& r, uint32_t width, uint32_t rows) {
  return passPlanes(r) ? VkDeviceSize(width) * rows * 16 * passPlanes(r) : 16;
}

// Rows of `width` vec4s per output or pass plane that one storage buffer holds
// (maxStorageBufferRange): the band height. The pass buffer holds all its planes' rows.
uint32_t rowsPerBuffer(const Renderer& r, uint32_t width) {
  const VkDeviceSize rowBytes = VkDeviceSize(width) * 16 * std::max(passPlanes(r), 1u);
  return uint32_t(std::min<VkDeviceSize>(r.device.properties.limits.maxStorageBufferRange / rowBytes, UINT32_MAX));
}

// The rows the output buffer holds (the band height), refusing before anything is allocated an
// output the device cannot hold. The kernel's output is a storage buffer of a vec4 per pixel
// within maxStorageBufferRange: over it, an image is rendered in bands of rows, but progressive
// rendering (the running sums, the viewer) needs it whole. All of it must fit the heap of
// host-visible memory.
uint32_t outputRows(const Renderer& r, uint32_t width, uint32_t height) {
  const uint32_t rows = r.accumulate ? height : std::min(height, rowsPerBuffer(r, width));
  const VkDeviceSize output = VkDeviceSize(width) * std::max(rows, 1u) * 16;
  const VkDeviceSize passes = passBytes(r, width, std::max(rows, 1u));
  const VkDeviceSize buffer = std::max(output, passes);
  const VkDeviceSize accumulation = (output + VkDeviceSize(width) * height * 4) * (r.secondAccumulation ? 2 : 1);
  const VkDeviceSize total = (r.accumulate ? output + accumulation : output) +
                             (passPlanes(r) ? passes : 0) + edgeListBytes(r, width, std::max(rows, 1u));
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const VkDeviceSize range = r.device.properties.limits.maxStorageBufferRange;
  if (buffer > range)
    throw VulkanError(size + " needs a " + mebibytes(buffer) + " output buffer" +
                      (r.accumulate ? " for progressive rendering" : " for one row") +
                      "; this device's storage buffers hold at most " + mebibytes(range) +
                      " (maxStorageBufferRange): render a smaller image");
  VkDeviceSize heap = 0;
  const VkPhysicalDeviceMemoryProperties& mem = r.device.memory;
  for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
    if (mem.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
      heap = std::max(heap, mem.memoryHeaps[mem.memoryTypes[i].heapIndex].size);
  if (total > heap)
    throw VulkanError(size + " needs " + mebibytes(total) + " of device memory; this device's host-visible heap holds " +
                      mebibytes(heap) + ": render a smaller image");
  return rows;
}

// Running sums and display pixels (progressive only; else 1 x 1, the binding exists), in GENERAL
// layout.
void createAccumulation(Renderer& r, uint32_t width, uint32_t height, Buffer& sums, Image& display) {
  destroyBuffer(r.device, sums);
  destroyImage(r.device, display);
  sums = createBuffer(r.device, accumulationBytes(r, width, height), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  display = createImage(r.device, r.accumulate ? width : 1, r.accumulate ? height : 1, 1, VK_FORMAT_R32_UINT,
                        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, false);
  VkCommandBuffer cmd = beginCommands(r.device);
  imageBarrier(cmd, display.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, 0, VK_ACCESS_SHADER_WRITE_BIT,
               VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  submitAndWait(r.device, cmd);
}

}  // namespace

bool outputFits(const Renderer& r, uint32_t width, uint32_t height) {
  const bool accumulationFits = r.accumulation.size == accumulationBytes(r, r.width, r.height) &&
                                (r.otherAccumulation.size == accumulationBytes(r, r.width, r.height)) == r.secondAccumulation;
  const bool passesFit = r.passes.size == passBytes(r, r.width, r.bandRows);
  const bool edgesFit = r.edgeList.size == edgeListBytes(r, r.width, r.bandRows);
  return width == r.width && height == r.height && r.pixels.buffer && accumulationFits && passesFit && edgesFit;
}

void createOutput(Renderer& r, uint32_t width, uint32_t height) {
  const uint32_t rows = outputRows(r, width, height);
  destroyBuffer(r.device, r.pixels);
  createAccumulation(r, width, height, r.accumulation, r.display);
  if (r.secondAccumulation) {
    createAccumulation(r, width, height, r.otherAccumulation, r.otherDisplay);
  } else {
    destroyBuffer(r.device, r.otherAccumulation);
    destroyImage(r.device, r.otherDisplay);
  }
  // A storage buffer in host-visible memory, not an image: the host reads it in place, and
  // lavapipe stores one vec4 per lane instead of one image channel per lane (docs/performance.md,
  // "Where the kernel's time goes").
  r.bandRows = rows;
  r.pixels = createBuffer(r.device, VkDeviceSize(width) * r.bandRows * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  destroyBuffer(r.device, r.passes);
  r.passes = createBuffer(r.device, passBytes(r, width, r.bandRows), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  destroyBuffer(r.device, r.edgeList);
  r.edgeList = createBuffer(r.device, edgeListBytes(r, width, r.bandRows),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  r.width = width;
  r.height = height;
}
