// Benchmark (prints numbers, asserts nothing): raytex's kernel against a yardstick, minimal
// hand-written compute kernels doing the same work (bench/yardstick/*.comp), on the same
// device in the same run. The project's performance target is a per-frame GPU time within
// 1.2x of the yardstick for the same work. Each kernel is dispatched once to warm up (lavapipe
// compiles at the first dispatch), then once per run, round-robin across kernels; the table
// holds the medians of the GPU timestamps around each dispatch.
//
// raytex renders the course scene (scenes/textures.cfg) as is, and with its sphere's material
// switched the way the notes say, parsed from edited text beside the file (no files written):
// "aChecker;" (vs checker.comp), "aMarble;" with 8 octaves in place of aMarble's default 6
// (vs marble.comp, which sums 8), the same at spp 4 (vs marble.comp's 2x2 build), and the
// objects removed (only the background: vs write.comp, the write-only floor).
//
// Usage: raytex_bench_yardstick [--width W] [--height H] [--runs N] [--dump DIR] [--validate]
//                               [SCENE]   (default scenes/textures.cfg, from the repository root)
// --dump DIR writes each kernel's image as PNG, the differences (x8) of each compared pair, and
// prints the pairs' max and mean differences (0..255 per sRGB channel).
// Run with VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json LP_NUM_THREADS=2.
#include "support/image_diff.h"
#include "common.h"
#include "gpu_scene.h"
#include "srgb.h"
#include "input_file.h"
#include "atomic_file.h"
#include "median.h"
#include "noise.h"
#include "noise_permutation.h"
#include "parser.h"
#include "renderer.h"
// Generated at build time by glslangValidator --vn (CMakeLists.txt, add_spirv).
#include "yardstick_checker_spv.h"
#include "yardstick_marble_2x2_spv.h"
#include "yardstick_marble_spv.h"
#include "yardstick_write_spv.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct Options {
  uint32_t width = 1920, height = 1080;
  int runs = 7;
  std::string scene = "scenes/textures.cfg";
  std::string dumpDir;  // empty: no images
  bool validate = false;
};

// --- the yardstick kernels: one descriptor set (output image, permutation table), a pipeline each

struct Yardstick {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
  Image output;        // rgba32f storage image, like raytex's
  Buffer permutation;  // uniform: the 512-entry table packed four to a uvec4
  Buffer readback;     // width * height * 4 floats
  VkQueryPool timestamps = VK_NULL_HANDLE;
  uint32_t width = 0, height = 0;
};

void createYardstick(Yardstick& y, const Device& device, uint32_t width, uint32_t height) {
  y.width = width;
  y.height = height;
  const VkDescriptorSetLayoutBinding bindings[] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo setLayoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setLayoutInfo.bindingCount = uint32_t(std::size(bindings));
  setLayoutInfo.pBindings = bindings;
  VK_CHECK(vkCreateDescriptorSetLayout(device.device, &setLayoutInfo, nullptr, &y.setLayout));

  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &y.setLayout;
  VK_CHECK(vkCreatePipelineLayout(device.device, &layoutInfo, nullptr, &y.pipelineLayout));

  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}, {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = uint32_t(std::size(sizes));
  poolInfo.pPoolSizes = sizes;
  VK_CHECK(vkCreateDescriptorPool(device.device, &poolInfo, nullptr, &y.descriptorPool));
  VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  setInfo.descriptorPool = y.descriptorPool;
  setInfo.descriptorSetCount = 1;
  setInfo.pSetLayouts = &y.setLayout;
  VK_CHECK(vkAllocateDescriptorSets(device.device, &setInfo, &y.descriptorSet));

  y.output = createImage(device, width, height, 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                         VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, false);
  y.readback = createBuffer(device, VkDeviceSize(width) * height * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  // raytex's permutation (host/reference/noise.cpp), so the two marbles can be compared by eye.
  const std::array<uint32_t, 512>& perm = noisePermutation();
  y.permutation = createBuffer(device, sizeof(perm), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  writeBuffer(y.permutation, perm.data(), sizeof(perm));

  VkDescriptorImageInfo imageInfo{VK_NULL_HANDLE, y.output.view, VK_IMAGE_LAYOUT_GENERAL};
  VkDescriptorBufferInfo bufferInfo{y.permutation.buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
  writes[0].dstSet = y.descriptorSet;
  writes[0].dstBinding = 0;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  writes[0].pImageInfo = &imageInfo;
  writes[1].dstSet = y.descriptorSet;
  writes[1].dstBinding = 1;
  writes[1].descriptorCount = 1;
  writes[1].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  writes[1].pBufferInfo = &bufferInfo;
  vkUpdateDescriptorSets(device.device, 2, writes, 0, nullptr);

  VkCommandBuffer cmd = beginCommands(device);
  imageBarrier(cmd, y.output.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, 0, VK_ACCESS_SHADER_WRITE_BIT,
               VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  submitAndWait(device, cmd);

  VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
  queryInfo.queryCount = 2;
  VK_CHECK(vkCreateQueryPool(device.device, &queryInfo, nullptr, &y.timestamps));
}

void destroyYardstick(Yardstick& y, const Device& device) {
  VkDevice d = device.device;
  vkDeviceWaitIdle(d);
  destroyImage(device, y.output);
  destroyBuffer(device, y.permutation);
  destroyBuffer(device, y.readback);
  if (y.timestamps) vkDestroyQueryPool(d, y.timestamps, nullptr);
  if (y.descriptorPool) vkDestroyDescriptorPool(d, y.descriptorPool, nullptr);
  if (y.pipelineLayout) vkDestroyPipelineLayout(d, y.pipelineLayout, nullptr);
  if (y.setLayout) vkDestroyDescriptorSetLayout(d, y.setLayout, nullptr);
  y = Yardstick{};
}

// Dispatches `pipeline` over the image and waits; returns the GPU time in ms (timestamps around
// the dispatch, as renderFrame does).
double dispatchYardstick(Yardstick& y, const Device& device, VkPipeline pipeline) {
  VkCommandBuffer cmd = beginCommands(device);
  // The previous frame's writes (or the readback's reads) come before this one's.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
  vkCmdResetQueryPool(cmd, y.timestamps, 0, 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, y.timestamps, 0);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, y.pipelineLayout, 0, 1, &y.descriptorSet, 0, nullptr);
  vkCmdDispatch(cmd, (y.width + 7) / 8, (y.height + 7) / 8, 1);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, y.timestamps, 1);
  submitAndWait(device, cmd);
  uint64_t ticks[2] = {0, 0};
  VK_CHECK(vkGetQueryPoolResults(device.device, y.timestamps, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  return double(ticks[1] - ticks[0]) * device.properties.limits.timestampPeriod * 1e-6;
}

// Records a copy of a storage image the kernel wrote (layout GENERAL) into a buffer the host
// reads, tightly packed, with the barriers on both sides; the image ends in GENERAL, so the next
// dispatch's writes wait for the copy.
void recordImageReadback(VkCommandBuffer cmd, VkImage image, VkBuffer buffer, uint32_t width, uint32_t height) {
  imageBarrier(cmd, image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_SHADER_WRITE_BIT,
               VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width, height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
  VkMemoryBarrier hostBarrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  hostBarrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  hostBarrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &hostBarrier, 0,
                       nullptr, 0, nullptr);
  imageBarrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_TRANSFER_READ_BIT,
               VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
}

// Copies the yardstick's image into its readback buffer; waits.
const float* readbackYardstick(Yardstick& y, const Device& device) {
  VkCommandBuffer cmd = beginCommands(device);
  recordImageReadback(cmd, y.output.image, y.readback.buffer, y.width, y.height);
  submitAndWait(device, cmd);
  return static_cast<const float*>(y.readback.data);
}

// --- raytex's scenes: the course scene's text, edited as the notes say

std::string readFile(const std::string& path) {
  std::string text, why;
  uint64_t size = 0;
  if (readWholeFile(path, uint64_t(1) << 30, &text, &why, &size) != ReadStatus::Read)
    throw std::runtime_error("cannot read " + path);
  return text;
}

// `text` with its first `from` replaced by `to`; throws if there is none (the scene changed).
std::string replaceFirst(std::string text, const std::string& from, const std::string& to, const std::string& file) {
  size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error(file + ": no '" + from + "' to replace");
  return text.replace(at, from.size(), to);
}

// The sphere's material named instead of aSolidChecker (as scripts/course-scene.sh does).
std::string sphereMaterial(const std::string& text, const std::string& material, const std::string& file) {
  std::string t = replaceFirst(text, "\n    aSolidChecker;", "\n    // aSolidChecker;", file);
  return replaceFirst(t, "\n    // " + material + ";", "\n    " + material + ";", file);
}

struct RaytexCase {
  std::string name;
  GpuScene scene;
  KernelKey key;
};

RaytexCase raytexCase(const std::string& name, const std::string& text, const std::string& path, uint32_t width,
                      uint32_t height, uint32_t samplesPerSide) {
  GpuScene scene = buildGpuScene(parseSceneText(text, path), width, height);
  // As raytex render builds it: around the scene's values.
  KernelOptions kernel;
  kernel.samplesPerSide = samplesPerSide;
  kernel.bakeValues = true;
  KernelKey key = kernelKey(scene, kernel);
  return {name, std::move(scene), key};
}

// raytex's frame: the scene uploaded (untimed), its pipeline current, one dispatch; GPU ms.
double renderRaytex(Renderer& r, const RaytexCase& c) {
  uploadScene(r, c.scene);
  preparePipeline(r, c.key);
  renderFrame(r);
  return r.lastFrameMs;
}

bool parseOptions(int argc, char** argv, Options* o) {
  bool positional = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    bool hasValue = i + 1 < argc;
    if (a == "--width" && hasValue) o->width = uint32_t(atoi(argv[++i]));
    else if (a == "--height" && hasValue) o->height = uint32_t(atoi(argv[++i]));
    else if (a == "--runs" && hasValue) o->runs = atoi(argv[++i]);
    else if (a == "--dump" && hasValue) o->dumpDir = argv[++i];
    else if (a == "--validate") o->validate = true;
    else if (a.rfind("--", 0) != 0 && !positional) {
      o->scene = a;
      positional = true;
    } else {
      return false;
    }
  }
  return o->width > 0 && o->height > 0 && o->width <= 16384 && o->height <= 16384 && o->runs >= 1;
}

void writePng(const std::string& dir, const std::string& name, const ImageRGBA8& image) {
  std::string path = dir + "/" + name + ".png";
  writePngAtomic(path, image);
  printf("  wrote %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  if (!parseOptions(argc, argv, &opt)) {
    fprintf(stderr,
            "usage: %s [--width W] [--height H] [--runs N] [--dump DIR] [--validate] [SCENE]\n"
            "  SCENE: the course scene, default scenes/textures.cfg\n",
            argv[0]);
    return 2;
  }
  const uint32_t width = opt.width, height = opt.height;
  try {
    // raytex's scenes: the course scene's text with the sphere's material switched; aMarble with
    // the yardstick's 8 octaves (its default is 6), by the included file's text edited in place.
    const std::string text = readFile(opt.scene);
    const std::string includeName = "texture_include.cfg";
    const std::string includeLine = "#include \"" + includeName + "\"";
    const std::string includePath = (std::filesystem::path(opt.scene).parent_path() / includeName).string();
    const std::string include = readFile(includePath);
    const std::string marbleInclude =
        replaceFirst(include, "texture = marble { }", "texture = marble { octaves = 8; }", includePath);
    const std::string marble8 = replaceFirst(text, includeLine, marbleInclude, opt.scene);
    const size_t objects = text.find("/* ---- objects ---- */");
    if (objects == std::string::npos) throw std::runtime_error(opt.scene + ": no '/* ---- objects ---- */'");
    std::vector<RaytexCase> raytex;
    raytex.push_back(raytexCase("background only (no objects)", text.substr(0, objects), opt.scene, width, height, 1));
    raytex.push_back(raytexCase("aChecker sphere", replaceFirst(text, "\n    aSolidChecker;", "\n    aChecker;", opt.scene),
                                opt.scene, width, height, 1));
    raytex.push_back(raytexCase("default (aSolidChecker)", text, opt.scene, width, height, 1));
    raytex.push_back(raytexCase("aMarble, 8 octaves", sphereMaterial(marble8, "aMarble", opt.scene), opt.scene, width,
                                height, 1));
    raytex.push_back(raytexCase("aMarble, 8 octaves, spp 4", sphereMaterial(marble8, "aMarble", opt.scene), opt.scene,
                                width, height, 2));

    DeviceOptions deviceOptions;
    deviceOptions.validation = opt.validate;
    Renderer r;
    createRenderer(r, deviceOptions);
    if (!r.timestamps) throw std::runtime_error("the device has no timestamps on its compute queue");
    Yardstick y;
    createYardstick(y, r.device, width, height);
    struct Kernel {
      const char* name;
      VkPipeline pipeline;
    };
    std::vector<Kernel> kernels = {
        {"write", createComputePipeline(r.device, y.pipelineLayout, yardstick_write_spv, sizeof(yardstick_write_spv))},
        {"checker", createComputePipeline(r.device, y.pipelineLayout, yardstick_checker_spv, sizeof(yardstick_checker_spv))},
        {"marble", createComputePipeline(r.device, y.pipelineLayout, yardstick_marble_spv, sizeof(yardstick_marble_spv))},
        {"marble_2x2",
         createComputePipeline(r.device, y.pipelineLayout, yardstick_marble_2x2_spv, sizeof(yardstick_marble_2x2_spv))}};

    // The table's rows: a yardstick kernel and the raytex case doing the same work.
    struct Row {
      const char* work;
      size_t kernel, raytexCase;
    };
    const Row rows[] = {{"write-only floor", 0, 0},
                        {"checker plane + lat-long checker sphere + Phong + shadow", 1, 1},
                        {"  (same yardstick) vs the default scene", 1, 2},
                        {"+ 8-octave marble", 2, 3},
                        {"+ 2x2 supersampling", 3, 4}};

    // Warm-up: lavapipe compiles each pipeline at its first dispatch.
    for (const Kernel& k : kernels) dispatchYardstick(y, r.device, k.pipeline);
    for (const RaytexCase& c : raytex) renderRaytex(r, c);

    // Interleaved: every run times each kernel once, yardstick and raytex alternating.
    std::vector<std::vector<double>> kernelMs(kernels.size()), raytexMs(raytex.size());
    for (int run = 0; run < opt.runs; ++run) {
      for (size_t i = 0; i < std::max(kernels.size(), raytex.size()); ++i) {
        if (i < kernels.size()) kernelMs[i].push_back(dispatchYardstick(y, r.device, kernels[i].pipeline));
        if (i < raytex.size()) raytexMs[i].push_back(renderRaytex(r, raytex[i]));
      }
    }

    const char* threads = getenv("LP_NUM_THREADS");
    printf("%s, %ux%u, %d runs (LP_NUM_THREADS=%s), median GPU ms per frame\n", r.device.properties.deviceName, width,
           height, opt.runs, threads ? threads : "unset");
    printf("%-58s %12s  %-28s %10s %7s\n", "work", "yardstick ms", "raytex scene", "raytex ms", "ratio");
    for (const Row& row : rows) {
      double yMs = median(kernelMs[row.kernel]), rMs = median(raytexMs[row.raytexCase]);
      printf("%-58s %12.2f  %-28s %10.2f %7.2f\n", row.work, yMs, raytex[row.raytexCase].name.c_str(), rMs,
             rMs / yMs);
    }

    if (!opt.dumpDir.empty()) {
      std::filesystem::create_directories(opt.dumpDir);
      const char* raytexFiles[] = {"raytex_background", "raytex_aChecker", "raytex_aSolidChecker", "raytex_aMarble8",
                                   "raytex_aMarble8_spp4"};
      std::vector<ImageRGBA8> kernelImages, raytexImages;
      for (const Kernel& k : kernels) {
        dispatchYardstick(y, r.device, k.pipeline);
        kernelImages.push_back(encodeSrgb(readbackYardstick(y, r.device), int(width), int(height)));
        writePng(opt.dumpDir, std::string("yardstick_") + k.name, kernelImages.back());
      }
      for (size_t i = 0; i < raytex.size(); ++i) {
        renderRaytex(r, raytex[i]);
        readbackFrame(r);
        raytexImages.push_back(encodeSrgb(framePixels(r), int(width), int(height)));
        writePng(opt.dumpDir, raytexFiles[i], raytexImages.back());
      }
      printf("%-58s %-28s %9s %9s\n", "yardstick vs raytex (sRGB 8-bit)", "raytex scene", "max diff", "mean diff");
      for (const Row& row : rows) {
        const ImageRGBA8& a = kernelImages[row.kernel];
        const ImageRGBA8& b = raytexImages[row.raytexCase];
        ImageDiff d = compareImages(a, b);
        printf("%-58s %-28s %9d %9.3f\n", kernels[row.kernel].name, raytex[row.raytexCase].name.c_str(), d.maxError,
               d.meanError);
        writePng(opt.dumpDir, std::string("diff_") + kernels[row.kernel].name + "_vs_" + raytexFiles[row.raytexCase],
                 diffImage(a, b));
      }
    }

    for (const Kernel& k : kernels) vkDestroyPipeline(r.device.device, k.pipeline, nullptr);
    destroyYardstick(y, r.device);
    int validationErrors = r.device.validationErrors;
    destroyRenderer(r);
    if (validationErrors > 0) {
      fprintf(stderr, "%d validation errors\n", validationErrors);
      return 1;
    }
  } catch (const std::exception& e) {
    fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
