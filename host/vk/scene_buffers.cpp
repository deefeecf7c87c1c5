#include "renderer.h"

#include "bindings.h"
#include "common.h"
#include "renderer_parts.h"
#include "scene_limits.h"

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

}  // namespace

void destroyImages(Renderer& r) {
  for (Image& image : r.images) destroyImage(r.device, image);
  r.images.clear();
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

  if (!outputFits(r, s.frame.width, s.frame.height)) createOutput(r, s.frame.width, s.frame.height);
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
