// A GLFW window with a Vulkan swapchain. The kernel's display pixels are copied into it: no
// graphics pipeline. GLFW 3.3 API only.
#pragma once

#include "device.h"
#include "resources.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

struct Window {
  GLFWwindow* window = nullptr;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{0, 0};
  std::vector<VkImage> images;
  VkSemaphore acquired = VK_NULL_HANDLE;      // the swapchain image is ready to be written
  VkSemaphore presentReady = VK_NULL_HANDLE;  // the copy is done
  Buffer composed;  // the display pixels read back for an overlay, then copied to the swapchain
};

// Starts GLFW. Throws VulkanError when there is no display to open a window on, or GLFW finds
// no Vulkan loader.
void initWindowSystem();
void shutdownWindowSystem();

// What the Vulkan instance and device need for windows (pass to DeviceOptions).
std::vector<const char*> windowInstanceExtensions();
bool windowPresentSupport(VkInstance instance, VkPhysicalDevice physical, uint32_t queueFamily);

// Opens the window (not yet visible to Vulkan); then createSwapchain once the device exists.
GLFWwindow* openWindow(int width, int height, const std::string& title);
void createSwapchain(Window& window, const Device& device);
void destroyWindow(Window& window, const Device& device);

// The framebuffer size in pixels (0 x 0 while minimised).
VkExtent2D framebufferSize(const Window& window);

// Whether the swapchain's bytes are B, G, R, A (else R, G, B, A): Renderer::displayBgra.
bool windowBgra(const Window& window);

// Copies `pixels` (the renderer's display image, GENERAL layout: 8-bit sRGB pixels in the
// swapchain's byte order, written by a completed dispatch) to the next swapchain image and
// presents. Returns false when the swapchain no longer matches the window (resize): call
// createSwapchain again.
bool presentPixels(Window& window, const Device& device, const Image& pixels);

// Copies `image` (r32ui display pixels, GENERAL layout, written by a completed dispatch) into
// `into`, a host-visible buffer (re-created at the image's size), readable once this returns.
void readImagePixels(const Device& device, const Image& image, Buffer& into);

// Draws over a copy of the display pixels (width x height, the image's byte order) before they
// reach the window.
using ComposeFn = std::function<void(uint32_t* pixels, uint32_t width, uint32_t height)>;

// presentPixels with `compose` run on the CPU over a copy of `pixels` (the image itself, which
// the next sample adds to, stays as the kernel wrote it).
bool presentComposed(Window& window, const Device& device, const Image& pixels, const ComposeFn& compose);
