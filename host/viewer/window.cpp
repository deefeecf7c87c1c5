#include "window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>

namespace {

void destroySwapchain(Window& w, const Device& d) {
  if (w.swapchain) vkDestroySwapchainKHR(d.device, w.swapchain, nullptr);
  w.swapchain = VK_NULL_HANDLE;
  w.images.clear();
}

// An 8-bit sRGB swapchain format: the kernel's display image holds sRGB-encoded bytes, which a
// copy stores as they are.
VkSurfaceFormatKHR chooseFormat(const Device& d, VkSurfaceKHR surface) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(d.physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(d.physical, surface, &count, formats.data()));
  // The kernel writes sRGB-encoded bytes; an _SRGB format stores them as they are, and so does
  // _UNORM with the sRGB colour space (the display decodes both the same way).
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM,
                          VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& f : formats)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  throw VulkanError("the display offers no 8-bit RGBA or BGRA sRGB swapchain format");
}

}  // namespace

void initWindowSystem() {
  if (!glfwInit())
    throw VulkanError("no display to open a window on (is DISPLAY set?); render to a file instead: "
                      "raytex render SCENE -o out.png");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw VulkanError("GLFW found no Vulkan loader; install libvulkan1, or use raytex render SCENE -o out.png");
  }
}

void shutdownWindowSystem() { glfwTerminate(); }

std::vector<const char*> windowInstanceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  return std::vector<const char*>(names, names + count);
}

bool windowPresentSupport(VkInstance instance, VkPhysicalDevice physical, uint32_t queueFamily) {
  return glfwGetPhysicalDevicePresentationSupport(instance, physical, queueFamily) == GLFW_TRUE;
}

GLFWwindow* openWindow(int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window) throw VulkanError("cannot open a window");
  return window;
}

VkExtent2D framebufferSize(const Window& w) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(w.window, &width, &height);
  return {uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0))};
}

void createSwapchain(Window& w, const Device& d) {
  VK_CHECK(vkDeviceWaitIdle(d.device));
  if (!w.surface) {
    VK_CHECK(glfwCreateWindowSurface(d.instance, w.window, nullptr, &w.surface));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(d.device, &semaphoreInfo, nullptr, &w.acquired));
    VK_CHECK(vkCreateSemaphore(d.device, &semaphoreInfo, nullptr, &w.presentReady));
  }
  VkBool32 supported = VK_FALSE;
  VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(d.physical, d.queueFamily, w.surface, &supported));
  if (!supported) throw VulkanError("the Vulkan queue cannot present to this window");

  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(d.physical, w.surface, &caps));
  VkSurfaceFormatKHR format = chooseFormat(d, w.surface);
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) extent = framebufferSize(w);
  extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = w.surface;
  info.minImageCount = std::max(caps.minImageCount, 2u);
  if (caps.maxImageCount > 0) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always available
  info.clipped = VK_TRUE;
  info.oldSwapchain = w.swapchain;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSwapchainKHR(d.device, &info, nullptr, &swapchain));
  destroySwapchain(w, d);
  w.swapchain = swapchain;
  w.format = format.format;
  w.extent = extent;
  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(d.device, w.swapchain, &count, nullptr));
  w.images.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(d.device, w.swapchain, &count, w.images.data()));
}

void destroyWindow(Window& w, const Device& d) {
  if (d.device) {
    vkDeviceWaitIdle(d.device);
    destroySwapchain(w, d);
    if (w.acquired) vkDestroySemaphore(d.device, w.acquired, nullptr);
    if (w.presentReady) vkDestroySemaphore(d.device, w.presentReady, nullptr);
    destroyBuffer(d, w.composed);
  }
  if (w.surface) vkDestroySurfaceKHR(d.instance, w.surface, nullptr);
  if (w.window) glfwDestroyWindow(w.window);
  w = Window{};
}

bool windowBgra(const Window& w) {
  return w.format == VK_FORMAT_B8G8R8A8_SRGB || w.format == VK_FORMAT_B8G8R8A8_UNORM;
}

namespace {

// Records the copy of `pixels` (or, when `composed`, of the buffer holding them) into the
// swapchain image `target`, with the barriers around it.
void recordCopyToSwapchain(VkCommandBuffer cmd, const Window& w, VkImage target, const Image& pixels,
                           const Buffer* composed) {
  imageBarrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  // Sizes differ only for the frame after a resize, before the swapchain follows it.
  const VkExtent3D extent{std::min(pixels.width, w.extent.width), std::min(pixels.height, w.extent.height), 1};
  if (composed) {
    VkBufferImageCopy region{};
    region.bufferRowLength = pixels.width;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = extent;
    vkCmdCopyBufferToImage(cmd, composed->buffer, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  } else {
    imageBarrier(cmd, pixels.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkImageCopy region{};  // r32ui and the 8-bit formats are in the same 32-bit compatibility class
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.extent = extent;
    vkCmdCopyImage(cmd, pixels.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   1, &region);
    imageBarrier(cmd, pixels.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                 VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  }
  imageBarrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
               VK_ACCESS_TRANSFER_WRITE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
}

// The swapchain's next image with the copy in it, presented; false when out of date.
bool copyAndPresent(Window& w, const Device& d, const Image& pixels, const Buffer* composed) {
  uint32_t index = 0;
  VkResult result = vkAcquireNextImageKHR(d.device, w.swapchain, UINT64_MAX, w.acquired, VK_NULL_HANDLE, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (result != VK_SUBOPTIMAL_KHR) VK_CHECK(result);
  VkCommandBuffer cmd = beginCommands(d);
  recordCopyToSwapchain(cmd, w, w.images[index], pixels, composed);
  submitAndWait(d, cmd, w.acquired, VK_PIPELINE_STAGE_TRANSFER_BIT, w.presentReady);

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &w.presentReady;
  present.swapchainCount = 1;
  present.pSwapchains = &w.swapchain;
  present.pImageIndices = &index;
  result = vkQueuePresentKHR(d.queue, &present);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
  VK_CHECK(result);
  return true;
}

}  // namespace

void readImagePixels(const Device& d, const Image& pixels, Buffer& into) {
  const VkDeviceSize bytes = VkDeviceSize(pixels.width) * pixels.height * 4;
  if (into.size != bytes) {
    destroyBuffer(d, into);
    into = createBuffer(d, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  }
  VkCommandBuffer cmd = beginCommands(d);
  imageBarrier(cmd, pixels.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_SHADER_WRITE_BIT,
               VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {pixels.width, pixels.height, 1};
  vkCmdCopyImageToBuffer(cmd, pixels.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, into.buffer, 1, &region);
  VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  toHost.buffer = into.buffer;
  toHost.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0,
                       nullptr);
  imageBarrier(cmd, pixels.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_TRANSFER_READ_BIT,
               VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  submitAndWait(d, cmd);
}

bool presentPixels(Window& w, const Device& d, const Image& pixels) { return copyAndPresent(w, d, pixels, nullptr); }

bool presentComposed(Window& w, const Device& d, const Image& pixels, const ComposeFn& compose) {
  readImagePixels(d, pixels, w.composed);
  compose(static_cast<uint32_t*>(w.composed.data), pixels.width, pixels.height);
  return copyAndPresent(w, d, pixels, &w.composed);
}
