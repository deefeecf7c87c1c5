// The trace kernel's specialised compute pipelines (its descriptor set: bindings.h).
#pragma once

#include "device.h"
#include "gpu_scene.h"

#include <cstdint>

VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout, const KernelKey& key);

// A compute pipeline from SPIR-V (`bytes` long), entry point main; the module is destroyed
// once the pipeline exists. Throws VulkanError.
VkPipeline createComputePipeline(const Device& device, VkPipelineLayout layout, const uint32_t* code, size_t bytes,
                                 const VkSpecializationInfo* specialization = nullptr,
                                 VkPipelineCreateFlags flags = 0);
