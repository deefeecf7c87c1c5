// Owns the device-side state of one scene and renders it: upload, specialised
// pipeline, dispatch, readback. Shared by every output (PNG, tests).
#pragma once

#include "device.h"
#include "gpu_scene.h"
#include "pipeline.h"
#include "resources.h"

#include <cstdint>

struct Renderer {
  Device device;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  PipelineKey pipelineKey;

  Buffer frame, spheres, planes, materials, lights, noise;
  Buffer readback;  // width * height * 4 floats
  Image output;     // rgba32f storage image
  Image images;     // sampler2DArray of image textures (1x1 placeholder when none)
  uint32_t width = 0, height = 0;
  VkQueryPool timestamps = VK_NULL_HANDLE;  // two per frame, around the dispatch
  double lastFrameMs = 0.0;  // GPU time of the last renderFrame (timestamps), else wall time
};

void createRenderer(Renderer& renderer, const DeviceOptions& options);
void destroyRenderer(Renderer& renderer);

// Replaces the scene on the device and the output size (re-creating only what changed size).
void uploadScene(Renderer& renderer, const GpuScene& scene);

// Rewrites the frame, sphere, plane and light buffers after packCamera (same counts and size).
void updateSceneBuffers(Renderer& renderer, const GpuScene& scene);

// Creates the pipeline specialised to `key` unless it is the current one.
void preparePipeline(Renderer& renderer, const PipelineKey& key);

// Dispatches the kernel over the whole image; waits. Sets lastFrameMs.
void renderFrame(Renderer& renderer);

// Copies the rendered image into the host-visible readback buffer; waits.
void readbackFrame(Renderer& renderer);

// Linear RGBA floats, row 0 at the top, valid after readbackFrame.
const float* framePixels(const Renderer& renderer);
