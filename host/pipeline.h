// The trace kernel's descriptor layout and its specialised compute pipelines.
#pragma once

#include "device.h"

#include <cstdint>

// Bindings of shaders/common.h (set 0).
VkDescriptorSetLayout createTraceSetLayout(const Device& device);

// The kernel specialised to a scene: textureKinds is the TEX_* bit mask (absent kinds are
// compiled out), outputMode one of OUTPUT_*, textureFilter one of FILTER_*.
VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout,
                               uint32_t textureKinds, uint32_t outputMode, uint32_t textureFilter);
