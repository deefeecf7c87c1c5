#include "resources.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace {

uint32_t findMemoryType(const Device& device, uint32_t typeBits, VkMemoryPropertyFlags wanted,
                        VkMemoryPropertyFlags preferred) {
  const VkPhysicalDeviceMemoryProperties& mem = device.memory;
  for (VkMemoryPropertyFlags flags : {wanted | preferred, wanted}) {
    for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
      if ((typeBits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  throw VulkanError("no Vulkan memory type with the required properties");
}

VkDeviceMemory allocate(const Device& device, const VkMemoryRequirements& req,
                        VkMemoryPropertyFlags wanted, VkMemoryPropertyFlags preferred) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = req.size;
  info.memoryTypeIndex = findMemoryType(device, req.memoryTypeBits, wanted, preferred);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkResult result = vkAllocateMemory(device.device, &info, nullptr, &memory);
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw VulkanError("out of memory: the Vulkan device could not allocate " + mebibytes(req.size) +
                      " (its memory heap holds " +
                      mebibytes(device.memory.memoryHeaps[device.memory.memoryTypes[info.memoryTypeIndex].heapIndex].size) +
                      "); try a smaller image");
  VK_CHECK(result);
  return memory;
}

}  // namespace

std::string mebibytes(VkDeviceSize bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage) {
  Buffer b;
  b.size = size > 0 ? size : 16;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = b.size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(device.device, &info, nullptr, &b.buffer));
  try {
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device.device, b.buffer, &req);
    // Buffers the device writes and the host reads (copy targets, the kernel's storage buffers)
    // prefer cached memory: uncached reads are slow on discrete GPUs.
    VkMemoryPropertyFlags preferred = (usage & (VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT))
                                          ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT
                                          : 0;
    b.memory = allocate(device, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                        preferred);
    VK_CHECK(vkBindBufferMemory(device.device, b.buffer, b.memory, 0));
    VK_CHECK(vkMapMemory(device.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.data));
  } catch (...) {
    destroyBuffer(device, b);  // no half-made buffer left behind
    throw;
  }
  return b;
}

void destroyBuffer(const Device& device, Buffer& b) {
  if (b.memory) vkFreeMemory(device.device, b.memory, nullptr);  // unmaps implicitly
  if (b.buffer) vkDestroyBuffer(device.device, b.buffer, nullptr);
  b = Buffer{};
}

void writeBuffer(Buffer& b, const void* data, VkDeviceSize size) {
  if (size > b.size) throw VulkanError("writeBuffer: data larger than buffer");
  if (size) memcpy(b.data, data, size);
}

Image createImage(const Device& device, uint32_t width, uint32_t height, uint32_t layers,
                  VkFormat format, VkImageUsageFlags usage, bool asArray, uint32_t levels) {
  Image img;
  img.format = format;
  img.width = width;
  img.height = height;
  img.layers = layers;
  img.levels = levels;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = levels;
  info.arrayLayers = layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vkCreateImage(device.device, &info, nullptr, &img.image));
  try {
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device.device, img.image, &req);
    img.memory = allocate(device, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
    VK_CHECK(vkBindImageMemory(device.device, img.image, img.memory, 0));

    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = img.image;
    viewInfo.viewType = asArray ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, layers};
    VK_CHECK(vkCreateImageView(device.device, &viewInfo, nullptr, &img.view));
  } catch (...) {
    destroyImage(device, img);
    throw;
  }
  return img;
}

void destroyImage(const Device& device, Image& img) {
  if (img.view) vkDestroyImageView(device.device, img.view, nullptr);
  if (img.image) vkDestroyImage(device.device, img.image, nullptr);
  if (img.memory) vkFreeMemory(device.device, img.memory, nullptr);
  img = Image{};
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkAccessFlags srcAccess, VkAccessFlags dstAccess,
                  VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

VkCommandBuffer beginCommands(const Device& device) {
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = device.commandPool;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(device.device, &info, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  return cmd;
}

void submitAndWait(const Device& device, VkCommandBuffer cmd, VkSemaphore wait, VkPipelineStageFlags waitStage,
                   VkSemaphore signal) {
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  VK_CHECK(vkCreateFence(device.device, &fenceInfo, nullptr, &fence));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  if (wait) {
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &wait;
    submit.pWaitDstStageMask = &waitStage;
  }
  if (signal) {
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &signal;
  }
  VkResult result = vkQueueSubmit(device.queue, 1, &submit, fence);
  if (result == VK_SUCCESS) result = vkWaitForFences(device.device, 1, &fence, VK_TRUE, UINT64_MAX);
  vkDestroyFence(device.device, fence, nullptr);
  vkFreeCommandBuffers(device.device, device.commandPool, 1, &cmd);
  VK_CHECK(result);
}

void uploadImageLayers(const Device& device, Image& image, std::initializer_list<HostBytes> parts) {
  // One copy region per mip level, each covering every layer.
  std::vector<VkBufferImageCopy> regions;
  VkDeviceSize total = 0;
  for (uint32_t level = 0; level < image.levels; ++level) {
    uint32_t w = std::max(1u, image.width >> level), h = std::max(1u, image.height >> level);
    VkBufferImageCopy region{};
    region.bufferOffset = total;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, image.layers};
    region.imageExtent = {w, h, 1};
    regions.push_back(region);
    total += VkDeviceSize(w) * h * image.layers * 4;
  }
  VkDeviceSize given = 0;
  for (const HostBytes& part : parts) given += part.size;
  if (given != total)
    throw VulkanError("uploadImageLayers: " + std::to_string(given) + " bytes for an image of " +
                      std::to_string(total));

  Buffer staging = createBuffer(device, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  VkDeviceSize offset = 0;
  for (const HostBytes& part : parts) {
    if (part.size) memcpy(static_cast<uint8_t*>(staging.data) + offset, part.data, part.size);
    offset += part.size;
  }
  VkCommandBuffer cmd = beginCommands(device);
  imageBarrier(cmd, image.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
  vkCmdCopyBufferToImage(cmd, staging.buffer, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         uint32_t(regions.size()), regions.data());
  imageBarrier(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  try {
    submitAndWait(device, cmd);
  } catch (...) {
    destroyBuffer(device, staging);
    throw;
  }
  destroyBuffer(device, staging);
}

void uploadImageLayers(const Device& device, Image& image, const void* pixels, VkDeviceSize bytes) {
  uploadImageLayers(device, image, {HostBytes{pixels, bytes}});
}
