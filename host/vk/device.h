// Vulkan instance, physical-device choice, logical device and compute queue.
#pragma once

#include "error.h"

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <vector>


const char* vkResultName(VkResult result);
[[noreturn]] void throwVkError(const char* call, VkResult result, const char* file, int line);

#define VK_CHECK(call)                                                    \
  do {                                                                    \
    VkResult vkCheckResult_ = (call);                                     \
    if (vkCheckResult_ != VK_SUCCESS)                                     \
      throwVkError(#call, vkCheckResult_, __FILE__, __LINE__);            \
  } while (0)

// Whether a queue family of a device can present to the window system (a window's need).
using PresentSupport = bool (*)(VkInstance, VkPhysicalDevice, uint32_t queueFamily);

struct DeviceOptions {
  int deviceIndex = -1;     // -1: best available (discrete > integrated > virtual > CPU)
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation if installed
  // For a window: the instance extensions the window system needs, and its present test;
  // with presentSupport set, the queue must also present and VK_KHR_swapchain is enabled.
  std::vector<const char*> instanceExtensions;
  PresentSupport presentSupport = nullptr;
};

struct Device {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  bool lavapipe = false;    // the driver is Mesa's lavapipe (VK_DRIVER_ID_MESA_LLVMPIPE): its limits apply
  bool validation = false;  // the layer is active
  int validationErrors = 0;  // errors the layer reported (messages go to stderr)
};

// Throws VulkanError; with no usable device, the message says how to install one.
void createDevice(Device& device, const DeviceOptions& options);
void destroyDevice(Device& device);

// One line per physical device: "index: name (type)".
std::string listDevices();
