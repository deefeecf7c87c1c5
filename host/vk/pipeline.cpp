#include "pipeline.h"

#include "common.h"
// Generated at build time by glslangValidator --vn (CMakeLists.txt, add_spirv).
#include "trace_aov_box_spv.h"
#include "trace_aov_box_tree_spv.h"
#include "trace_aov_point_spv.h"
#include "trace_aov_point_tree_spv.h"
#include "trace_box_samples_spv.h"
#include "trace_box_samples_tree_spv.h"
#include "trace_box_spv.h"
#include "trace_box_tree_spv.h"
#include "trace_debug_spv.h"
#include "trace_debug_tree_spv.h"
#include "trace_edges_spv.h"
#include "trace_edges_tree_spv.h"
#include "trace_point_samples_spv.h"
#include "trace_point_samples_tree_spv.h"
#include "trace_point_spv.h"
#include "trace_point_tree_spv.h"

#include <cstddef>
#include <vector>

VkDescriptorSetLayout createTraceSetLayout(const Device& device) {
  auto binding = [](uint32_t index, VkDescriptorType type, uint32_t count = 1) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = index;
    b.descriptorType = type;
    b.descriptorCount = count;
    b.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    return b;
  };
  const VkDescriptorSetLayoutBinding bindings[] = {
      binding(BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_SPHERES, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_PLANES, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_NOISE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_IMAGES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, MAX_IMAGES),
      binding(BINDING_ACCUMULATION, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_DISPLAY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
      binding(BINDING_TREE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_TREE_STORAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_SPHERE_STORAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_STATUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_TILE_RANGES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_TILE_SPHERES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_TILE_ORDER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC),
      binding(BINDING_AOV, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_EDGE_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
  };
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = uint32_t(std::size(bindings));
  info.pBindings = bindings;
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device.device, &info, nullptr, &layout));
  return layout;
}

VkPipeline createComputePipeline(const Device& device, VkPipelineLayout layout, const uint32_t* code, size_t bytes,
                                 const VkSpecializationInfo* specialization, VkPipelineCreateFlags flags) {
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = bytes;
  moduleInfo.pCode = code;
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device.device, &moduleInfo, nullptr, &module));
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.flags = flags;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = specialization;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateComputePipelines(device.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device.device, module, nullptr);
  VK_CHECK(result);
  return pipeline;
}

namespace {

struct SpirvModule {
  const uint32_t* code;
  size_t bytes;
};
#define SPIRV_MODULE(name) SpirvModule{name, sizeof(name)}

// The build variant: debug outputs, or the shaded image with point or box textures, from one
// sample per dispatch or N x N samples in one (trace.comp.glsl, RAYTEX_SUPERSAMPLE), or with
// passes (RAYTEX_AOV: either); each with the sphere tree's code where the scene walks one
// (RAYTEX_SPHERE_TREE).
SpirvModule traceVariant(const KernelKey& key) {
  const bool tree = key.shape.sphereTree != SPHERE_TREE_NONE;
  const bool samples = key.samplesPerSide > 1 && !key.progressive;
  const bool filtered = key.textureFilter != FILTER_POINT;  // FILTER_COVERAGE's main kernel is the box one
  if (key.outputMode != OUTPUT_SHADED) return tree ? SPIRV_MODULE(trace_debug_tree_spv) : SPIRV_MODULE(trace_debug_spv);
  if (key.edgePass) return tree ? SPIRV_MODULE(trace_edges_tree_spv) : SPIRV_MODULE(trace_edges_spv);
  if (key.passMask != 0 && filtered)
    return tree ? SPIRV_MODULE(trace_aov_box_tree_spv) : SPIRV_MODULE(trace_aov_box_spv);
  if (key.passMask != 0) return tree ? SPIRV_MODULE(trace_aov_point_tree_spv) : SPIRV_MODULE(trace_aov_point_spv);
  if (filtered && samples)
    return tree ? SPIRV_MODULE(trace_box_samples_tree_spv) : SPIRV_MODULE(trace_box_samples_spv);
  if (filtered) return tree ? SPIRV_MODULE(trace_box_tree_spv) : SPIRV_MODULE(trace_box_spv);
  if (samples) return tree ? SPIRV_MODULE(trace_point_samples_tree_spv) : SPIRV_MODULE(trace_point_samples_spv);
  return tree ? SPIRV_MODULE(trace_point_tree_spv) : SPIRV_MODULE(trace_point_spv);
}

}  // namespace

VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout, const KernelKey& key) {
  const SpirvModule variant = traceVariant(key);

  std::vector<VkSpecializationMapEntry> entries = {
      {SPEC_SPHERE_TEXTURE_KINDS, offsetof(KernelKey, shape.sphereKinds), sizeof(uint32_t)},
      {SPEC_PLANE_TEXTURE_KINDS, offsetof(KernelKey, shape.planeKinds), sizeof(uint32_t)},
      {SPEC_SPHERE_COUNT, offsetof(KernelKey, shape.sphereCount), sizeof(uint32_t)},
      {SPEC_PLANE_COUNT, offsetof(KernelKey, shape.planeCount), sizeof(uint32_t)},
      {SPEC_LIGHT_COUNT, offsetof(KernelKey, shape.lightCount), sizeof(uint32_t)},
      {SPEC_TEXTURE_PLACEMENT, offsetof(KernelKey, shape.placed), sizeof(VkBool32)},
      {SPEC_IMAGE_COUNT, offsetof(KernelKey, shape.imageCount), sizeof(uint32_t)},
      {SPEC_SPHERE_TREE, offsetof(KernelKey, shape.sphereTree), sizeof(uint32_t)},
      {SPEC_LOOP_BUDGET, offsetof(KernelKey, loopBudget), sizeof(uint32_t)},
      {SPEC_TILE_LISTS, offsetof(KernelKey, shape.tileLists), sizeof(VkBool32)},
      {SPEC_SHADOW_LISTS, offsetof(KernelKey, shape.shadowLists), sizeof(VkBool32)},
      {SPEC_TILE_ORDER, offsetof(KernelKey, tileOrder), sizeof(VkBool32)},
      {SPEC_OUTPUT_MODE, offsetof(KernelKey, outputMode), sizeof(uint32_t)},
      {SPEC_SAMPLES_PER_SIDE, offsetof(KernelKey, samplesPerSide), sizeof(uint32_t)},
      {SPEC_PROGRESSIVE, offsetof(KernelKey, progressive), sizeof(VkBool32)},
      {SPEC_BAKED, offsetof(KernelKey, baked.enabled), sizeof(VkBool32)},
      {SPEC_BAKED_MATERIAL_COUNT, offsetof(KernelKey, baked.materialCount), sizeof(uint32_t)},
      {SPEC_TEXTURE_FILTER, offsetof(KernelKey, textureFilter), sizeof(uint32_t)},
      {SPEC_IMAGE_FILTER, offsetof(KernelKey, imageFilter), sizeof(uint32_t)},
  };
  // Only the pass variant declares the pass mask: without passes the constants are as before it.
  if (key.passMask != 0) entries.push_back({SPEC_PASS_MASK, offsetof(KernelKey, passMask), sizeof(uint32_t)});
  for (uint32_t i = 0; key.baked.enabled && i < BAKED_WORD_COUNT; ++i)
    entries.push_back({SPEC_BAKED_WORDS + i, uint32_t(offsetof(KernelKey, baked.words) + 4 * i), sizeof(uint32_t)});
  VkSpecializationInfo specialization{};
  specialization.mapEntryCount = uint32_t(entries.size());
  specialization.pMapEntries = entries.data();
  specialization.dataSize = sizeof(KernelKey);
  specialization.pData = &key;
  // warmPipeline dispatches past the image: the base needs VK_PIPELINE_CREATE_DISPATCH_BASE_BIT.
  return createComputePipeline(device, layout, variant.code, variant.bytes, &specialization,
                               VK_PIPELINE_CREATE_DISPATCH_BASE_BIT);
}
