// Owns the device-side state of one scene and renders it: upload, specialised pipelines,
// dispatch, readback. Shared by every output (PNG, tests). Its functions live by concern:
// renderer.cpp (create, destroy), scene_buffers.cpp (uploadScene, updateSceneBuffers),
// frame_buffers.cpp (the output, pass, accumulation and edge-list buffers), frame_kernels.cpp
// (preparePipeline, prepareTileKernels, pipelineWarm, warmPipeline) and dispatch.cpp
// (selectBand, renderFrame, renderSample, readbackFrame, the pixels and passes).
#pragma once

#include "device.h"
#include "gpu_scene.h"
#include "passes.h"
#include "pipeline.h"
#include "resources.h"
#include "tile_kernels.h"

#include <cstdint>
#include <vector>

// A dispatch whose loops passed the loop budget (common.h, SPEC_LOOP_BUDGET): part of its work
// was not done, and its image is not to be used. A runtime failure, exit code 1.
struct LoopBudgetError : VulkanError {
  using VulkanError::VulkanError;
};

struct CachedPipeline {
  KernelKey key;
  VkPipeline pipeline = VK_NULL_HANDLE;
  bool dispatched = false;  // lavapipe compiles to machine code at the first dispatch
};

// One dispatch of a tile kernel (tile_kernels.h): its workgroups render the `count` tiles of the
// tile order from byte `offset` (the dynamic offset of BINDING_TILE_ORDER).
struct TileDispatch {
  KernelKey key;
  VkPipeline pipeline = VK_NULL_HANDLE;
  uint32_t offset = 0, count = 0;
};

struct Renderer {
  Device device;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;  // the current one, from `pipelines`
  KernelKey pipelineKey;
  std::vector<CachedPipeline> pipelines;  // every one created, kept for switching back

  Buffer frame, spheres, planes, materials, lights, noise;
  // The sphere tree's nodes (uniform, a placeholder block without a tree) and, over the uniform
  // blocks' sizes, its nodes and the spheres in storage buffers (else 16-byte placeholders).
  Buffer tree, treeStorage, sphereStorage;
  Buffer tileRanges, tileSpheres;  // primary rays' per-tile sphere lists (placeholders without)
  // The tile kernels' tiles (BINDING_TILE_ORDER; word 0 TILE_ORDER_NONE), as last written, and
  // their dispatches; none: `pipeline` renders the whole image.
  Buffer tileOrder;
  std::vector<uint32_t> tileOrderWords;
  std::vector<TileDispatch> tileDispatches;
  Buffer status;  // BINDING_STATUS: what the kernel reports (the loop budget), cleared per frame
  // The float image the host reads: width * height * 4 floats of linear radiance, written by
  // the kernel (BINDING_OUTPUT) or, progressive, by readbackFrame.
  Buffer pixels;
  // The passes (AOVs) written beside the image: bit (1 << AOV_*) per pass, set before
  // uploadScene, which sizes `passes`; every kernel prepared then writes them (KernelKey::passMask,
  // the pass variant), from the pixel centre. Progressive rendering writes them in the dispatch
  // of sample 0 (renderSample); the viewer requests none.
  uint32_t passMask = 0;
  // BINDING_AOV: per pass in passMask, in bit order, a plane of width * bandHeight vec4s (16 bytes
  // without passes). With passes the band height is chosen so that all the planes fit one buffer.
  Buffer passes;
  // FILTER_COVERAGE (shaders/coverage.glsl), set before uploadScene, which sizes the list of
  // edge pixels (BINDING_EDGE_LIST; a 16-byte placeholder without); the edge pass of the current
  // key (from `pipelines`; none unless it is FILTER_COVERAGE).
  bool coverage = false;
  Buffer edgeList;
  VkPipeline edgePipeline = VK_NULL_HANDLE;
  KernelKey edgeKey;
  Buffer accumulation;  // progressive sums, width * height * 4 floats when `accumulate`
  Image display;        // r32ui: progressive means as 8-bit sRGB pixels (1 x 1 unless `accumulate`)
  bool accumulate = false;  // set before uploadScene to render progressively (the viewer; headless
                            // renders over lavapipe's loop limit, headless.cpp)
  // The viewer's split screen, set before uploadScene with `accumulate`: a second set of running
  // sums and display pixels, which swapAccumulation exchanges with the one the kernels write.
  bool secondAccumulation = false;
  Buffer otherAccumulation;
  Image otherDisplay;
  uint32_t displayBgra = 0;  // 1: `display` in B, G, R, A byte order (Frame.displayBgra)
  float sampleWeight = 1.0f;  // of the last renderSample: readbackFrame's mean = sum * weight
  // BINDING_IMAGES' elements: each scene image at its own size; `placeholder` (1 x 1) in the rest.
  std::vector<Image> images;
  Image placeholder;
  uint32_t width = 0, height = 0;
  // The output holds bandRows rows: the whole image, or as many as one storage buffer holds
  // (maxStorageBufferRange); the dispatches and readbacks cover the band from bandFirstRow.
  uint32_t bandRows = 0;
  uint32_t bandFirstRow = 0;
  VkQueryPool timestamps = VK_NULL_HANDLE;  // two per frame, around the dispatch
  double lastFrameMs = 0.0;  // GPU time of the last renderFrame (timestamps), else wall time
};

void createRenderer(Renderer& renderer, const DeviceOptions& options);
void destroyRenderer(Renderer& renderer);

// Replaces the scene on the device and the output size and passes (re-creating only what
// changed size).
void uploadScene(Renderer& renderer, const GpuScene& scene);

// Rewrites the frame, sphere, plane and light buffers after packCamera (same counts and size).
void updateSceneBuffers(Renderer& renderer, const GpuScene& scene);

// Makes the pipeline specialised to `key` the current one, creating it unless created before.
// On lavapipe every pipeline counts its loops against the driver's limit (key.loopBudget is set
// here, for the device).
void preparePipeline(Renderer& renderer, const KernelKey& key);

// Makes `plan`'s kernels (key specialised to each one's kinds) render the frame, each over its
// tiles, creating those not created before; a plan without kernels: preparePipeline(key). The
// image is one band (bandCount 1).
void prepareTileKernels(Renderer& renderer, const KernelKey& key, const TilePlan& plan);

// Whether the pipeline for `key` exists and has run (lavapipe compiles at the first dispatch).
bool pipelineWarm(const Renderer& renderer, const KernelKey& key);

// Creates the pipeline for `key` and dispatches it once over no pixels, so that a later switch
// to it costs nothing; the current pipeline and the image stay as they were. Waits.
void warmPipeline(Renderer& renderer, const KernelKey& key);

// How many bands of bandRows rows the image takes (1 unless over maxStorageBufferRange).
uint32_t bandCount(const Renderer& renderer);
// Makes the band from row firstRow (a multiple of bandRows) the one renderFrame renders and
// readbackFrame reads. uploadScene selects band 0.
void selectBand(Renderer& renderer, uint32_t firstRow);
// Rows in the selected band.
uint32_t bandHeight(const Renderer& renderer);

// Dispatches the kernel over the selected band (the whole image when it is one), and for
// FILTER_COVERAGE the edge pass after it; waits. Sets lastFrameMs
// (all of them). Throws LoopBudgetError if a group of pixels passed the loop budget (lavapipe).
void renderFrame(Renderer& renderer);

// Progressive pipelines: adds sample `index` (0 restarts) of the N x N grid to the running sums
// and writes their mean as 8-bit sRGB to `display`; readbackFrame gives the mean in float.
// After N * N of them it is bit-identical to renderFrame's image with the N x N pipeline.
void renderSample(Renderer& renderer, uint32_t index);

// Makes the second accumulation set (secondAccumulation) the one the kernels add samples to and
// write display pixels from, and the current one the other: two methods accumulate side by side.
void swapAccumulation(Renderer& renderer);

// The pixels the last renderFrame's edge pass shaded again (FILTER_COVERAGE), else 0.
uint32_t edgePixelCount(const Renderer& renderer);

// Makes the rendered image and its passes visible to the host; waits.
void readbackFrame(Renderer& renderer);

// Linear RGBA floats of the selected band, its row 0 at the top, valid after readbackFrame.
const float* framePixels(const Renderer& renderer);

// The selected band's values of `pass`, a vec4 per pixel as common.h's AOV_* define them (values
// in xyz, coverage in w; position camera-relative: worldPositions adds the eye), its row 0 at
// the top, valid after readbackFrame; nullptr unless passMask holds the pass.
const float* passPixels(const Renderer& renderer, Pass pass);
