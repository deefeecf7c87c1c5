// The trace kernel's descriptor set (set 0): one row per BINDING_* of shaders/common.h, with its
// descriptor type, its count and the renderer's resource behind it. The set layout, the
// descriptor pool's sizes and the descriptor writes are all made from these rows; the kernel declares each binding once
// (shaders/trace.comp.glsl), and the validation layers check the two against each other.
#pragma once

#include "renderer.h"

#include <cstdint>
#include <vector>

struct TraceBinding {
  uint32_t binding;                   // BINDING_*
  VkDescriptorType type;
  uint32_t count;                     // descriptors: MAX_IMAGES for the images, else 1
  Buffer Renderer::*buffer;           // the buffer bound (a buffer type), else nullptr
  VkDeviceSize range;                 // the bytes bound: VK_WHOLE_SIZE, or a dynamic block's
};

// Every binding, in BINDING_* order.
const std::vector<TraceBinding>& traceBindings();

VkDescriptorSetLayout createTraceSetLayout(const Device& device);

// The descriptors of one set of that layout, per descriptor type: the pool's sizes.
std::vector<VkDescriptorPoolSize> traceDescriptorCounts();

// Points each binding of r.descriptorSet at its resource: the buffers, r.display, and the
// scene's images (r.placeholder past them), all with r.sampler.
void writeTraceDescriptors(Renderer& r);
