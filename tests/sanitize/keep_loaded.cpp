// Linked into every program of the sanitizer build (CMakeLists.txt, RAYTEX_SANITIZE): keeps the
// Vulkan driver and the validation layer loaded until exit. The Vulkan loader unloads them at
// vkDestroyInstance, before LeakSanitizer looks, and a leak in an unloaded library has no name
// to suppress by (tests/sanitize/lsan.supp). RTLD_LOCAL: their symbols stay out of the global
// scope, so that no call of the program binds to them instead of the loader.
#include <dlfcn.h>

#include <initializer_list>

namespace {

__attribute__((constructor)) void keepVulkanLibrariesLoaded() {
  for (const char* library : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"})
    dlopen(library, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);  // absent: nothing to keep
}

}  // namespace
