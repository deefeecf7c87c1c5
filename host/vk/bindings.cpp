#include "bindings.h"

#include "common.h"

#include <algorithm>

namespace {

constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;

std::vector<TraceBinding> makeBindings() {
  using R = Renderer;
  const VkDeviceSize whole = VK_WHOLE_SIZE;
  return {
      {BINDING_OUTPUT, kStorage, 1, &R::pixels, whole},
      {BINDING_FRAME, kUniform, 1, &R::frame, whole},
      {BINDING_SPHERES, kUniform, 1, &R::spheres, whole},
      {BINDING_PLANES, kUniform, 1, &R::planes, whole},
      {BINDING_MATERIALS, kUniform, 1, &R::materials, whole},
      {BINDING_LIGHTS, kUniform, 1, &R::lights, whole},
      {BINDING_NOISE, kUniform, 1, &R::noise, whole},
      {BINDING_IMAGES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, MAX_IMAGES, nullptr, 0},
      {BINDING_ACCUMULATION, kStorage, 1, &R::accumulation, whole},
      {BINDING_DISPLAY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, nullptr, 0},
      {BINDING_TREE, kUniform, 1, &R::tree, whole},
      {BINDING_TREE_STORAGE, kStorage, 1, &R::treeStorage, whole},
      {BINDING_SPHERE_STORAGE, kStorage, 1, &R::sphereStorage, whole},
      {BINDING_STATUS, kStorage, 1, &R::status, whole},
      {BINDING_TILE_RANGES, kStorage, 1, &R::tileRanges, whole},
      {BINDING_TILE_SPHERES, kStorage, 1, &R::tileSpheres, whole},
      // One tile kernel's block of the tile order, at the dispatch's dynamic offset.
      {BINDING_TILE_ORDER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, &R::tileOrder, 4 * TILE_ORDER_CHUNK},
      {BINDING_AOV, kStorage, 1, &R::passes, whole},
      {BINDING_EDGE_LIST, kStorage, 1, &R::edgeList, whole},
  };
}

}  // namespace

const std::vector<TraceBinding>& traceBindings() {
  static const std::vector<TraceBinding> bindings = makeBindings();
  return bindings;
}

VkDescriptorSetLayout createTraceSetLayout(const Device& device) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const TraceBinding& row : traceBindings()) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = row.binding;
    b.descriptorType = row.type;
    b.descriptorCount = row.count;
    b.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    bindings.push_back(b);
  }
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = uint32_t(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device.device, &info, nullptr, &layout));
  return layout;
}

std::vector<VkDescriptorPoolSize> traceDescriptorCounts() {
  std::vector<VkDescriptorPoolSize> sizes;
  for (const TraceBinding& row : traceBindings()) {
    auto same = [&](const VkDescriptorPoolSize& s) { return s.type == row.type; };
    auto it = std::find_if(sizes.begin(), sizes.end(), same);
    if (it == sizes.end()) sizes.push_back({row.type, row.count});
    else it->descriptorCount += row.count;
  }
  return sizes;
}

void writeTraceDescriptors(Renderer& r) {
  const auto& rows = traceBindings();
  const VkDescriptorImageInfo displayInfo{VK_NULL_HANDLE, r.display.view, VK_IMAGE_LAYOUT_GENERAL};
  VkDescriptorImageInfo imagesInfo[MAX_IMAGES];
  for (size_t i = 0; i < MAX_IMAGES; ++i)
    imagesInfo[i] = {r.sampler, (i < r.images.size() ? r.images[i] : r.placeholder).view,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  std::vector<VkDescriptorBufferInfo> buffers(rows.size());  // pointed into by the writes
  std::vector<VkWriteDescriptorSet> writes;
  for (size_t i = 0; i < rows.size(); ++i) {
    const TraceBinding& row = rows[i];
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = r.descriptorSet;
    w.dstBinding = row.binding;
    w.descriptorCount = row.count;
    w.descriptorType = row.type;
    if (row.buffer) {
      buffers[i] = {(r.*row.buffer).buffer, 0, row.range};
      w.pBufferInfo = &buffers[i];
    } else {
      w.pImageInfo = row.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ? &displayInfo : imagesInfo;
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(r.device.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}
