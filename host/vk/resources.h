// Buffers, images and one-shot command submission: plain structs, free functions.
#pragma once

#include "device.h"

#include <initializer_list>
#include <string>

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* data = nullptr;  // persistently mapped (every buffer here is host-visible)
  VkDeviceSize size = 0;
};

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  uint32_t width = 0, height = 0, layers = 0;
  uint32_t levels = 1;  // mip levels; level l is max(1, width >> l) x max(1, height >> l)
};

// Host-visible, coherent, mapped. size 0 is rounded up to 16 bytes so a binding always exists.
// Out of memory: a VulkanError naming the size (nothing left allocated).
Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage);
void destroyBuffer(const Device& device, Buffer& buffer);
// Copies into a mapped buffer.
void writeBuffer(Buffer& buffer, const void* data, VkDeviceSize size);

// Device-local 2D (array) image with a view of type 2D_ARRAY when layers > 1 or asArray, and
// `levels` mip levels (the view covers them all).
Image createImage(const Device& device, uint32_t width, uint32_t height, uint32_t layers,
                  VkFormat format, VkImageUsageFlags usage, bool asArray, uint32_t levels = 1);
void destroyImage(const Device& device, Image& image);

// Records an image layout transition covering all layers and mip levels (synchronization2-free,
// plain barriers).
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkAccessFlags srcAccess, VkAccessFlags dstAccess,
                  VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage);

// Allocates a primary command buffer and begins it for one submission.
VkCommandBuffer beginCommands(const Device& device);
// Ends, submits, waits on a fence and frees the command buffer. Optionally the submission
// waits for `wait` at `waitStage` and signals `signal` (swapchain presentation).
void submitAndWait(const Device& device, VkCommandBuffer cmd, VkSemaphore wait = VK_NULL_HANDLE,
                   VkPipelineStageFlags waitStage = 0, VkSemaphore signal = VK_NULL_HANDLE);

// Uploads tightly packed RGBA8 texels into every layer and mip level of `image` (layout ends
// SHADER_READ_ONLY_OPTIMAL): level 0 of every layer (layer after layer), then level 1, and so on.
// The bytes may come in pieces, concatenated in order (e.g. level 0, then the other levels).
// Throws VulkanError unless they add up to the image's size.
struct HostBytes {
  const void* data;
  VkDeviceSize size;
};
void uploadImageLayers(const Device& device, Image& image, std::initializer_list<HostBytes> parts);
void uploadImageLayers(const Device& device, Image& image, const void* pixels, VkDeviceSize bytes);

// "N MiB", rounded up: sizes in messages.
std::string mebibytes(VkDeviceSize bytes);
