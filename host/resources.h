// Buffers, images and one-shot command submission: plain structs, free functions.
#pragma once

#include "device.h"

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
};

// Host-visible, coherent, mapped. size 0 is rounded up to 16 bytes so a binding always exists.
Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage);
void destroyBuffer(const Device& device, Buffer& buffer);
// Copies into a mapped buffer.
void writeBuffer(Buffer& buffer, const void* data, VkDeviceSize size);

// Device-local 2D (array) image with a view of type 2D_ARRAY when layers > 1 or asArray.
Image createImage(const Device& device, uint32_t width, uint32_t height, uint32_t layers,
                  VkFormat format, VkImageUsageFlags usage, bool asArray);
void destroyImage(const Device& device, Image& image);

// Records an image layout transition covering all layers (synchronization2-free, plain barriers).
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkAccessFlags srcAccess, VkAccessFlags dstAccess,
                  VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage);

// Allocates a primary command buffer and begins it for one submission.
VkCommandBuffer beginCommands(const Device& device);
// Ends, submits, waits on a fence and frees the command buffer.
void submitAndWait(const Device& device, VkCommandBuffer cmd);

// Uploads tightly packed RGBA8 layers into `image` (layout ends SHADER_READ_ONLY_OPTIMAL).
void uploadImageLayers(const Device& device, Image& image, const void* pixels, VkDeviceSize bytes);
