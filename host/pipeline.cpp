#include "pipeline.h"

#include "common.h"
#include "trace_comp_spv.h"  // generated at build time by glslangValidator --vn

#include <cstddef>

VkDescriptorSetLayout createTraceSetLayout(const Device& device) {
  auto binding = [](uint32_t index, VkDescriptorType type) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = index;
    b.descriptorType = type;
    b.descriptorCount = 1;
    b.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    return b;
  };
  const VkDescriptorSetLayoutBinding bindings[] = {
      binding(BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
      binding(BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_SPHERES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_PLANES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      binding(BINDING_NOISE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
      binding(BINDING_IMAGES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER),
  };
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = uint32_t(std::size(bindings));
  info.pBindings = bindings;
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device.device, &info, nullptr, &layout));
  return layout;
}

VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout,
                               uint32_t textureKinds, uint32_t outputMode, uint32_t textureFilter) {
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = sizeof(trace_comp_spv);
  moduleInfo.pCode = trace_comp_spv;
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device.device, &moduleInfo, nullptr, &module));

  struct Constants {
    uint32_t textureKinds;
    uint32_t outputMode;
    uint32_t textureFilter;
  } constants{textureKinds, outputMode, textureFilter};
  const VkSpecializationMapEntry entries[] = {
      {SPEC_TEXTURE_KINDS, offsetof(Constants, textureKinds), sizeof(uint32_t)},
      {SPEC_OUTPUT_MODE, offsetof(Constants, outputMode), sizeof(uint32_t)},
      {SPEC_TEXTURE_FILTER, offsetof(Constants, textureFilter), sizeof(uint32_t)},
  };
  VkSpecializationInfo specialization{};
  specialization.mapEntryCount = uint32_t(std::size(entries));
  specialization.pMapEntries = entries;
  specialization.dataSize = sizeof(constants);
  specialization.pData = &constants;

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = &specialization;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateComputePipelines(device.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device.device, module, nullptr);
  VK_CHECK(result);
  return pipeline;
}
