#include "device.h"

#include <cstdio>
#include <cstring>
#include <iterator>
#include <vector>

namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
const char* kNoDeviceHint =
    "no Vulkan device found: install a Vulkan driver, e.g. `apt-get install mesa-vulkan-drivers` "
    "(lavapipe, CPU)";

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    static_cast<Device*>(user)->validationErrors++;
    fprintf(stderr, "validation error: %s\n", data->pMessage);
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    fprintf(stderr, "validation warning: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  for (const VkLayerProperties& layer : layers)
    if (strcmp(layer.layerName, name) == 0) return true;
  return false;
}

bool layerHasExtension(const char* layer, const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()) != VK_SUCCESS) return false;
  for (const VkExtensionProperties& e : extensions)
    if (strcmp(e.extensionName, name) == 0) return true;
  return false;
}

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;  // lavapipe: never skipped
    default: return 0;
  }
}

const char* typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

// A family with compute (and, for a window, present) support.
bool computeQueueFamily(VkInstance instance, VkPhysicalDevice physical, PresentSupport present, uint32_t* family) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) && (!present || present(instance, physical, i))) {
      *family = i;
      return true;
    }
  }
  return false;
}

VkInstance createInstance(bool validation, const std::vector<const char*>& windowExtensions = {}) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "raytex";
  app.apiVersion = VK_API_VERSION_1_2;

  std::vector<const char*> extensions = windowExtensions;
  if (validation) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  // With validation, synchronization validation too: hazards between the kernel's writes,
  // the readback and the copies to the swapchain are errors like any other.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = uint32_t(std::size(enables));
  features.pEnabledValidationFeatures = enables;
  if (validation) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &kValidationLayer;
    if (layerHasExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
      extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
      info.pNext = &features;
    }
  }
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) throw VulkanError(kNoDeviceHint);
  VK_CHECK(result);
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

}  // namespace

const char* vkResultName(VkResult result) {
  switch (result) {
#define CASE(r) \
  case r: return #r;
    CASE(VK_SUCCESS)
    CASE(VK_NOT_READY)
    CASE(VK_TIMEOUT)
    CASE(VK_INCOMPLETE)
    CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    CASE(VK_ERROR_INITIALIZATION_FAILED)
    CASE(VK_ERROR_DEVICE_LOST)
    CASE(VK_ERROR_MEMORY_MAP_FAILED)
    CASE(VK_ERROR_LAYER_NOT_PRESENT)
    CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    CASE(VK_ERROR_TOO_MANY_OBJECTS)
    CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    CASE(VK_ERROR_FRAGMENTED_POOL)
    CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    CASE(VK_ERROR_UNKNOWN)
#undef CASE
    default: return "VkResult(unknown)";
  }
}

void throwVkError(const char* call, VkResult result, const char* file, int line) {
  throw VulkanError(std::string(call) + " failed: " + vkResultName(result) + " (" + file + ":" +
                    std::to_string(line) + ")");
}

// The driver of a physical device (Vulkan 1.2 core).
static VkDriverId driverId(VkPhysicalDevice physical) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &driver;
  vkGetPhysicalDeviceProperties2(physical, &properties);
  return driver.driverID;
}

// Validation messages go to debugCallback, which counts the errors.
static void createMessenger(Device& d) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = debugCallback;
  info.pUserData = &d;
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(d.instance, "vkCreateDebugUtilsMessengerEXT"));
  if (create) VK_CHECK(create(d.instance, &info, nullptr, &d.messenger));
}

// The physical device and its queue family: --device N, else the best type with a compute
// queue (that presents, for a window).
static void choosePhysicalDevice(Device& d, const DeviceOptions& options) {
  std::vector<VkPhysicalDevice> devices = physicalDevices(d.instance);
  if (devices.empty()) throw VulkanError(kNoDeviceHint);
  if (options.deviceIndex >= 0) {
    if (options.deviceIndex >= int(devices.size()))
      throw VulkanError("--device " + std::to_string(options.deviceIndex) + ": only " +
                        std::to_string(devices.size()) + " Vulkan device(s):\n" + listDevices());
    d.physical = devices[options.deviceIndex];
    if (!computeQueueFamily(d.instance, d.physical, options.presentSupport, &d.queueFamily))
      throw VulkanError("--device " + std::to_string(options.deviceIndex) + " has no compute queue" +
                        (options.presentSupport ? " that can present to this display" : ""));
    return;
  }
  int bestRank = -1;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(candidate, &props);
    uint32_t family = 0;
    if (!computeQueueFamily(d.instance, candidate, options.presentSupport, &family)) continue;
    if (typeRank(props.deviceType) > bestRank) {
      bestRank = typeRank(props.deviceType);
      d.physical = candidate;
      d.queueFamily = family;
    }
  }
  if (!d.physical) throw VulkanError(kNoDeviceHint);
}

// The logical device with one queue (and the swapchain extension, for a window), and a
// command pool on it.
static void createLogicalDevice(Device& d, bool present) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = d.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  const char* swapchainExtension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  if (present) {
    deviceInfo.enabledExtensionCount = 1;
    deviceInfo.ppEnabledExtensionNames = &swapchainExtension;
  }
  VK_CHECK(vkCreateDevice(d.physical, &deviceInfo, nullptr, &d.device));
  vkGetDeviceQueue(d.device, d.queueFamily, 0, &d.queue);
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = d.queueFamily;
  VK_CHECK(vkCreateCommandPool(d.device, &poolInfo, nullptr, &d.commandPool));
}

void createDevice(Device& d, const DeviceOptions& options) {
  d.validation = options.validation && hasLayer(kValidationLayer);
  if (options.validation && !d.validation)
    fprintf(stderr, "warning: %s is not installed (apt-get install vulkan-validationlayers)\n", kValidationLayer);
  d.instance = createInstance(d.validation, options.instanceExtensions);
  if (d.validation) createMessenger(d);
  choosePhysicalDevice(d, options);
  vkGetPhysicalDeviceProperties(d.physical, &d.properties);
  vkGetPhysicalDeviceMemoryProperties(d.physical, &d.memory);
  d.lavapipe = driverId(d.physical) == VK_DRIVER_ID_MESA_LLVMPIPE;
  createLogicalDevice(d, options.presentSupport != nullptr);
}

void destroyDevice(Device& d) {
  if (d.device) {
    vkDeviceWaitIdle(d.device);
    vkDestroyCommandPool(d.device, d.commandPool, nullptr);
    vkDestroyDevice(d.device, nullptr);
  }
  if (d.messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(d.instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(d.instance, d.messenger, nullptr);
  }
  if (d.instance) vkDestroyInstance(d.instance, nullptr);
  d = Device{};
}

std::string listDevices() {
  std::string out;
  VkInstance instance = VK_NULL_HANDLE;
  try {
    instance = createInstance(false);
    std::vector<VkPhysicalDevice> devices = physicalDevices(instance);
    for (size_t i = 0; i < devices.size(); ++i) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties(devices[i], &props);
      out += "  " + std::to_string(i) + ": " + props.deviceName + " (" + typeName(props.deviceType) + ")\n";
    }
  } catch (const VulkanError& e) {
    out += std::string("  ") + e.what() + "\n";
  }
  if (instance) vkDestroyInstance(instance, nullptr);
  return out;
}
