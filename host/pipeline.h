// The trace kernel's descriptor layout and its specialised compute pipelines.
#pragma once

#include "device.h"
#include "gpu_scene.h"

#include <cstdint>

// Bindings of shaders/common.h (set 0).
VkDescriptorSetLayout createTraceSetLayout(const Device& device);

// What a trace pipeline is specialised to (the SPEC_* constants of common.h).
struct PipelineKey {
  SceneShape shape;              // kinds per shape (absent ones compiled out), counts
  uint32_t outputMode = 0;       // OUTPUT_*
  uint32_t textureFilter = 0;    // FILTER_*: selects the kernel's build variant
  uint32_t samplesPerSide = 1;   // N x N samples per pixel
  uint32_t progressive = 0;      // 1: one sample per dispatch, accumulated (SPEC_PROGRESSIVE)
  BakedScene baked;              // the scene's values (SPEC_BAKED), when its camera is fixed
  bool operator==(const PipelineKey& o) const {
    return shape == o.shape && outputMode == o.outputMode &&
           textureFilter == o.textureFilter && samplesPerSide == o.samplesPerSide &&
           progressive == o.progressive && baked == o.baked;
  }
};

VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout, const PipelineKey& key);

// A compute pipeline from SPIR-V (`bytes` long), entry point main; the module is destroyed
// once the pipeline exists. Throws VulkanError.
VkPipeline createComputePipeline(const Device& device, VkPipelineLayout layout, const uint32_t* code, size_t bytes,
                                 const VkSpecializationInfo* specialization = nullptr,
                                 VkPipelineCreateFlags flags = 0, VkPipelineCache cache = VK_NULL_HANDLE);
