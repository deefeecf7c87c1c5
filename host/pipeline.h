// The trace kernel's descriptor layout and its specialised compute pipelines.
#pragma once

#include "device.h"

#include <cstdint>

// Bindings of shaders/common.h (set 0).
VkDescriptorSetLayout createTraceSetLayout(const Device& device);

// What a trace pipeline is specialised to (the SPEC_* constants of common.h).
struct PipelineKey {
  uint32_t textureKinds = 0;     // TEX_* bit mask: absent kinds are compiled out
  uint32_t outputMode = 0;       // OUTPUT_*
  uint32_t textureFilter = 0;    // FILTER_*: selects the kernel's build variant
  uint32_t samplesPerSide = 1;   // N x N samples per pixel
  uint32_t progressive = 0;      // 1: one sample per dispatch, accumulated (SPEC_PROGRESSIVE)
  bool operator==(const PipelineKey& o) const {
    return textureKinds == o.textureKinds && outputMode == o.outputMode &&
           textureFilter == o.textureFilter && samplesPerSide == o.samplesPerSide &&
           progressive == o.progressive;
  }
};

VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout, const PipelineKey& key);
