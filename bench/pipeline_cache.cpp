// Does the driver keep anything in a VkPipelineCache? Creates the (unspecialised) trace
// pipeline three times, each through a cache created from the previous one's data, and
// prints the data size and creation time. A cache that stays at its 32-byte header (lavapipe
// 22.3) cannot shorten start-up, so raytex keeps no pipeline cache file (docs/performance.md).
// Usage: raytex_bench_pipeline_cache [DEVICE_INDEX]
#include "device.h"
#include "bindings.h"
#include "pipeline.h"
#include "trace_point_spv.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

// The trace kernel's unspecialised pipeline (trace_point_spv) created through `cache`; the
// module is destroyed once the pipeline exists.
VkPipeline createCachedTracePipeline(const Device& d, VkPipelineLayout layout, VkPipelineCache cache) {
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = sizeof(trace_point_spv);
  moduleInfo.pCode = trace_point_spv;
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(d.device, &moduleInfo, nullptr, &module));
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateComputePipelines(d.device, cache, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(d.device, module, nullptr);
  VK_CHECK(result);
  return pipeline;
}

}  // namespace

int main(int argc, char** argv) {
  Device d;
  try {
    createDevice(d, {argc > 1 ? atoi(argv[1]) : -1, false});
    VkDescriptorSetLayout setLayout = createTraceSetLayout(d);
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(d.device, &layoutInfo, nullptr, &layout));
    printf("%s\n", d.properties.deviceName);
    std::vector<char> data;
    for (int pass = 0; pass < 3; ++pass) {
      VkPipelineCacheCreateInfo cacheInfo{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
      cacheInfo.initialDataSize = data.size();
      cacheInfo.pInitialData = data.empty() ? nullptr : data.data();
      VkPipelineCache cache = VK_NULL_HANDLE;
      VK_CHECK(vkCreatePipelineCache(d.device, &cacheInfo, nullptr, &cache));
      auto start = std::chrono::steady_clock::now();
      VkPipeline pipeline = createCachedTracePipeline(d, layout, cache);
      double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      size_t size = 0;
      VK_CHECK(vkGetPipelineCacheData(d.device, cache, &size, nullptr));
      data.resize(size);
      VK_CHECK(vkGetPipelineCacheData(d.device, cache, &size, data.data()));
      printf("pass %d: cache in %zu bytes, pipeline created in %.1f ms, cache out %zu bytes\n", pass,
             cacheInfo.initialDataSize, ms, size);
      vkDestroyPipeline(d.device, pipeline, nullptr);
      vkDestroyPipelineCache(d.device, cache, nullptr);
    }
    vkDestroyPipelineLayout(d.device, layout, nullptr);
    vkDestroyDescriptorSetLayout(d.device, setLayout, nullptr);
  } catch (const std::exception& e) {
    fprintf(stderr, "%s\n", e.what());
    destroyDevice(d);
    return 1;
  }
  destroyDevice(d);
  return 0;
}
