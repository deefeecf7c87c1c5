#include "renderer.h"

#include "bindings.h"
#include "common.h"
#include "pipeline.h"
#include "scene_limits.h"

#include <algorithm>
#include <bitset>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// Replaces `buffer` with a uniform buffer of the whole block the kernel declares, `capacity`
// items, the first `count` from `data`.
template <typename T>
void replaceUniformBuffer(Renderer& r, Buffer& buffer, const T* data, size_t count, size_t capacity = 1) {
  std::vector<T> block(data, data + count);
  block.resize(capacity);
  destroyBuffer(r.device, buffer);
  buffer = createBuffer(r.device, sizeof(T) * capacity, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  writeBuffer(buffer, block.data(), sizeof(T) * capacity);
}

// Replaces `buffer` with a storage buffer of `count` items from `data` (16 bytes when empty).
template <typename T>
void replaceStorageBuffer(Renderer& r, Buffer& buffer, const T* data, size_t count) {
  destroyBuffer(r.device, buffer);
  buffer = createBuffer(r.device, sizeof(T) * count, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  writeBuffer(buffer, data, sizeof(T) * count);
}

// The spheres and the tree's nodes where the kernel reads them (SceneShape::sphereTree):
// uniform blocks, or storage buffers over their sizes; the unused ones hold nothing.
void replaceSphereBuffers(Renderer& r, const GpuScene& s) {
  const bool storage = s.shape.sphereTree == SPHERE_TREE_STORAGE;
  const size_t uniformSpheres = storage ? 0 : s.spheres.size();
  replaceUniformBuffer(r, r.spheres, s.spheres.data(), uniformSpheres, MAX_UNIFORM_SPHERES);
  replaceUniformBuffer(r, r.tree, s.treeNodes.data(), storage ? 0 : s.treeNodes.size(), MAX_UNIFORM_TREE_NODES);
  replaceStorageBuffer(r, r.sphereStorage, s.spheres.data(), storage ? s.spheres.size() : 0);
  replaceStorageBuffer(r, r.treeStorage, s.treeNodes.data(), storage ? s.treeNodes.size() : 0);
}

// The per-tile lists (their sizes change with the camera).
void replaceTileBuffers(Renderer& r, const GpuScene& s) {
  replaceStorageBuffer(r, r.tileRanges, s.tiles.ranges.data(), s.tiles.ranges.size());
  replaceStorageBuffer(r, r.tileSpheres, s.tiles.spheres.data(), s.tiles.spheres.size());
}

// Writes `count` items into a storage buffer, replacing it only when they do not fit; returns
// whether it was replaced (its descriptor then needs writing).
template <typename T>
bool refillStorageBuffer(Renderer& r, Buffer& buffer, const T* data, size_t count) {
  if (sizeof(T) * count <= buffer.size) {
    writeBuffer(buffer, data, sizeof(T) * count);
    return false;
  }
  replaceStorageBuffer(r, buffer, data, count);
  return true;
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

void destroyImages(Renderer& r) {
  for (Image& image : r.images) destroyImage(r.device, image);
  r.images.clear();
}

// The 1 x 1 image in the elements of BINDING_IMAGES past the scene's images (magenta: a
// kernel that reads one shows it).
void createPlaceholderImage(Renderer& r) {
  static const uint8_t magenta[4] = {255, 0, 255, 255};
  r.placeholder = createImage(r.device, 1, 1, 1, VK_FORMAT_R8G8B8A8_SRGB,
                              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, false);
  uploadImageLayers(r.device, r.placeholder, magenta, sizeof(magenta));
}

// Throws VulkanError (the device destroyed) when its uniform buffers cannot hold the largest
// block the kernel declares (common.h): 64 KiB is common, 16 KiB the minimum.
void checkUniformRange(Device& device) {
  const size_t largestBlock = std::max({sizeof(gpu::Sphere) * MAX_UNIFORM_SPHERES, sizeof(gpu::Plane) * MAX_PLANES,
                                        sizeof(gpu::Material) * MAX_MATERIALS, sizeof(gpu::Light) * MAX_LIGHTS,
                                        sizeof(gpu::BvhNode) * MAX_UNIFORM_TREE_NODES});
  const uint32_t maxRange = device.properties.limits.maxUniformBufferRange;
  if (maxRange >= largestBlock) return;
  std::string name = device.properties.deviceName;
  destroyDevice(device);
  throw VulkanError(name + ": uniform buffers of at most " + std::to_string(maxRange) + " bytes; raytex needs " +
                    std::to_string(largestBlock));
}

// The pipeline layout of the one descriptor set, and that set.
void createDescriptorSet(Renderer& r) {
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &r.setLayout;
  VK_CHECK(vkCreatePipelineLayout(r.device.device, &layoutInfo, nullptr, &r.pipelineLayout));
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
                                        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 7},
                                        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1},
                                        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 9},
                                        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, MAX_IMAGES}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = uint32_t(std::size(sizes));
  poolInfo.pPoolSizes = sizes;
  VK_CHECK(vkCreateDescriptorPool(r.device.device, &poolInfo, nullptr, &r.descriptorPool));
  VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  setInfo.descriptorPool = r.descriptorPool;
  setInfo.descriptorSetCount = 1;
  setInfo.pSetLayouts = &r.setLayout;
  VK_CHECK(vkAllocateDescriptorSets(r.device.device, &setInfo, &r.descriptorSet));
}

// Bilinear, repeating: u wraps around the sphere and tiles repeat on planes (the kernel clamps
// the coordinate of wrap = clamp images itself, kinds/image.glsl). Trilinear between mip
// levels: the point kernel reads level 0 only (textureLod 0), the filtered kernel picks a level
// from the sample's footprint (kinds/image.glsl, imageBox). No maxLod limit: each view's level
// count is the limit. One sampler for every element of BINDING_IMAGES.
void createSampler(Renderer& r) {
  VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  samplerInfo.magFilter = VK_FILTER_LINEAR;
  samplerInfo.minFilter = VK_FILTER_LINEAR;
  samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  samplerInfo.maxLod = VK_LOD_CLAMP_NONE;
  VK_CHECK(vkCreateSampler(r.device.device, &samplerInfo, nullptr, &r.sampler));
}

// GPU frame times, where the queue supports timestamps.
void createTimestamps(Renderer& r) {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(r.device.physical, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(r.device.physical, &familyCount, families.data());
  if (families[r.device.queueFamily].timestampValidBits == 0 || r.device.properties.limits.timestampPeriod <= 0.0f)
    return;
  VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
  queryInfo.queryCount = 2;
  VK_CHECK(vkCreateQueryPool(r.device.device, &queryInfo, nullptr, &r.timestamps));
}

}  // namespace

void createRenderer(Renderer& r, const DeviceOptions& options) {
  createDevice(r.device, options);
  checkUniformRange(r.device);
  r.setLayout = createTraceSetLayout(r.device);
  createPlaceholderImage(r);
  r.status = createBuffer(r.device, sizeof(uint32_t) * STATUS_WORDS, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  const uint32_t clear[STATUS_WORDS] = {};
  writeBuffer(r.status, clear, sizeof(clear));
  writeTileOrder(r, {TILE_ORDER_NONE});
  createDescriptorSet(r);
  createSampler(r);
  createTimestamps(r);
}

void destroyRenderer(Renderer& r) {
  if (r.device.device) {
    VkDevice d = r.device.device;
    vkDeviceWaitIdle(d);
    for (CachedPipeline& p : r.pipelines) vkDestroyPipeline(d, p.pipeline, nullptr);
    for (Buffer* b : {&r.frame, &r.spheres, &r.planes, &r.materials, &r.lights, &r.noise, &r.pixels,
                      &r.accumulation, &r.tree, &r.treeStorage, &r.sphereStorage, &r.status, &r.tileRanges,
                      &r.tileSpheres, &r.tileOrder, &r.passes, &r.edgeList, &r.otherAccumulation})
      destroyBuffer(r.device, *b);
    destroyImage(r.device, r.display);
    destroyImage(r.device, r.otherDisplay);
    destroyImages(r);
    destroyImage(r.device, r.placeholder);
    if (r.sampler) vkDestroySampler(d, r.sampler, nullptr);
    if (r.timestamps) vkDestroyQueryPool(d, r.timestamps, nullptr);
    if (r.descriptorPool) vkDestroyDescriptorPool(d, r.descriptorPool, nullptr);
    if (r.pipelineLayout) vkDestroyPipelineLayout(d, r.pipelineLayout, nullptr);
    if (r.setLayout) vkDestroyDescriptorSetLayout(d, r.setLayout, nullptr);
  }
  destroyDevice(r.device);
  r = Renderer{};
}

void uploadScene(Renderer& r, const GpuScene& s) {
  // Checked before anything is replaced: the viewer keeps its last scene when this throws.
  const VkPhysicalDeviceLimits& limits = r.device.properties.limits;
  std::string over = imagesOverDeviceLimits(s.images, limits.maxImageDimension2D);
  if (!over.empty()) throw VulkanError(over);
  VK_CHECK(vkDeviceWaitIdle(r.device.device));
  // Whole blocks (buildGpuScene keeps to the MAX_* counts); the noise table even when unused.
  replaceUniformBuffer(r, r.frame, &s.frame, 1);
  replaceSphereBuffers(r, s);
  replaceTileBuffers(r, s);
  replaceUniformBuffer(r, r.planes, s.planes.data(), s.planes.size(), MAX_PLANES);
  replaceUniformBuffer(r, r.materials, s.materials.data(), s.materials.size(), MAX_MATERIALS);
  replaceUniformBuffer(r, r.lights, s.lights.data(), s.lights.size(), MAX_LIGHTS);
  replaceUniformBuffer(r, r.noise, &s.noise, 1);

  destroyImages(r);
  for (const ImageChain& chain : s.imageChains) {
    r.images.push_back(createImage(r.device, uint32_t(chain.width), uint32_t(chain.height), 1, VK_FORMAT_R8G8B8A8_SRGB,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, false,
                                   uint32_t(chain.levels)));
    uploadImageLayers(r.device, r.images.back(), chain.pixels.data(), chain.pixels.size());
  }

  bool accumulationFits = r.accumulation.size == accumulationBytes(r, r.width, r.height) &&
                          (r.otherAccumulation.size == accumulationBytes(r, r.width, r.height)) == r.secondAccumulation;
  bool passesFit = r.passes.size == passBytes(r, r.width, r.bandRows);
  bool edgesFit = r.edgeList.size == edgeListBytes(r, r.width, r.bandRows);
  if (s.frame.width != r.width || s.frame.height != r.height || !r.pixels.buffer || !accumulationFits || !passesFit ||
      !edgesFit)
    createOutput(r, s.frame.width, s.frame.height);
  selectBand(r, 0);
  writeTraceDescriptors(r);
}

void updateSceneBuffers(Renderer& r, const GpuScene& s) {
  VK_CHECK(vkDeviceWaitIdle(r.device.device));
  writeBuffer(r.frame, &s.frame, sizeof(s.frame));
  selectBand(r, r.bandFirstRow);
  const bool storage = s.shape.sphereTree == SPHERE_TREE_STORAGE;
  writeBuffer(storage ? r.sphereStorage : r.spheres, s.spheres.data(), sizeof(gpu::Sphere) * s.spheres.size());
  writeBuffer(storage ? r.treeStorage : r.tree, s.treeNodes.data(), sizeof(gpu::BvhNode) * s.treeNodes.size());
  // The lists change length with the camera: the buffers grow when they must, not per move.
  bool replaced = refillStorageBuffer(r, r.tileRanges, s.tiles.ranges.data(), s.tiles.ranges.size());
  replaced |= refillStorageBuffer(r, r.tileSpheres, s.tiles.spheres.data(), s.tiles.spheres.size());
  if (replaced) writeTraceDescriptors(r);
  writeBuffer(r.planes, s.planes.data(), sizeof(gpu::Plane) * s.planes.size());
  writeBuffer(r.lights, s.lights.data(), sizeof(gpu::Light) * s.lights.size());
}

namespace {

// The key with the device's loop budget (lavapipe's limit, none elsewhere) and the passes the
// pass buffer holds.
KernelKey budgeted(const Renderer& r, KernelKey key) {
  key.loopBudget = r.device.lavapipe ? uint32_t(kMaxLoopIterations) : 0u;
  key.passMask = r.passMask;
  return key;
}

CachedPipeline& cachedPipeline(Renderer& r, const KernelKey& unbudgeted) {
  const KernelKey key = budgeted(r, unbudgeted);
  for (CachedPipeline& p : r.pipelines)
    if (p.key == key) return p;
  r.pipelines.push_back({key, createTracePipeline(r.device, r.pipelineLayout, key), false});
  return r.pipelines.back();
}

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

// `tileOffset`: the dynamic offset of BINDING_TILE_ORDER (a tile kernel's tiles).
void bindAndDispatch(Renderer& r, VkCommandBuffer cmd, VkPipeline pipeline, uint32_t baseX, uint32_t groupsX,
                     uint32_t groupsY, uint32_t tileOffset = 0) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipelineLayout, 0, 1, &r.descriptorSet, 1,
                          &tileOffset);
  vkCmdDispatchBase(cmd, baseX, 0, 0, groupsX, groupsY, 1);
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
