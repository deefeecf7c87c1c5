#include "pipeline.h"

#include "common.h"
// Generated at build time by glslangValidator --vn (CMakeLists.txt, add_spirv).
#include "trace_variants.h"
#include "trace_variants_spv.h"

#include <cstddef>
#include <string>
#include <vector>

VkPipeline createComputePipeline(const Device& device, VkPipelineLayout layout, const uint32_t* code, size_t bytes,
                                 const VkSpecializationInfo* specialization, VkPipelineCreateFlags flags) {
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = bytes;
  moduleInfo.pCode = code;
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device.device, &moduleInfo, nullptr, &module));
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.flags = flags;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = specialization;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateComputePipelines(device.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device.device, module, nullptr);
  VK_CHECK(result);
  return pipeline;
}

namespace {

struct SpirvModule {
  const uint32_t* code;
  size_t bytes;
};
#define SPIRV_MODULE(name) SpirvModule{name, sizeof(name)}

// What a variant is compiled with (the columns of trace_variants.h), as bits.
enum VariantFeature : uint32_t { kBox = 1, kSamples = 2, kDebug = 4, kPasses = 8, kEdges = 16 };

struct TraceVariant {
  uint32_t features;
  SpirvModule plain, tree;  // without and with RAYTEX_SPHERE_TREE
};

#define RAYTEX_VARIANT_ROW(name, box, samples, debug, aov, edges)                                     \
  {(box ? kBox : 0u) | (samples ? kSamples : 0u) | (debug ? kDebug : 0u) | (aov ? kPasses : 0u) |     \
       (edges ? kEdges : 0u),                                                                          \
   SPIRV_MODULE(trace_##name##_spv), SPIRV_MODULE(trace_##name##_tree_spv)},
const TraceVariant kVariants[] = {RAYTEX_TRACE_VARIANTS(RAYTEX_VARIANT_ROW)};
#undef RAYTEX_VARIANT_ROW

// The features a key's kernel needs: the debug outputs alone; the edge pass (box textures); or
// the shaded image with box textures or point ones, with passes (one sample or N x N) or
// without them from N x N samples in one dispatch.
uint32_t featuresOf(const KernelKey& key) {
  if (key.outputMode != OUTPUT_SHADED) return kDebug;
  if (key.edgePass) return kEdges | kBox;
  const bool samples = key.samplesPerSide > 1 && !key.progressive;
  const uint32_t box = key.textureFilter != FILTER_POINT ? kBox : 0u;  // FILTER_COVERAGE's main kernel is the box one
  if (key.passMask != 0) return kPasses | box;
  return (samples ? kSamples : 0u) | box;
}

// The module of the row with the key's features, with the sphere tree's code where the scene
// walks one.
SpirvModule traceVariant(const KernelKey& key) {
  const uint32_t features = featuresOf(key);
  for (const TraceVariant& v : kVariants)
    if (v.features == features) return key.shape.sphereTree != SPHERE_TREE_NONE ? v.tree : v.plain;
  throw Error(ErrorKind::Internal, "no trace kernel variant has the features " + std::to_string(features));
}

}  // namespace

VkPipeline createTracePipeline(const Device& device, VkPipelineLayout layout, const KernelKey& key) {
  const SpirvModule variant = traceVariant(key);

  std::vector<VkSpecializationMapEntry> entries;
  for (const SpecConstant& c : specConstants())
    if (!c.declared || c.declared(key))
      for (uint32_t i = 0; i < c.words; ++i) entries.push_back({c.id + i, c.offset + 4 * i, sizeof(uint32_t)});
  VkSpecializationInfo specialization{};
  specialization.mapEntryCount = uint32_t(entries.size());
  specialization.pMapEntries = entries.data();
  specialization.dataSize = sizeof(KernelKey);
  specialization.pData = &key;
  // warmPipeline dispatches past the image: the base needs VK_PIPELINE_CREATE_DISPATCH_BASE_BIT.
  return createComputePipeline(device, layout, variant.code, variant.bytes, &specialization,
                               VK_PIPELINE_CREATE_DISPATCH_BASE_BIT);
}
