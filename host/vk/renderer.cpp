#include "renderer.h"

#include "bindings.h"
#include "common.h"
#include "renderer_parts.h"

#include <algorithm>
#include <string>
#include <vector>

namespace {

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
  const std::vector<VkDescriptorPoolSize> sizes = traceDescriptorCounts();
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
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
