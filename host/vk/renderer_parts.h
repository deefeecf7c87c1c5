// What the renderer's files (renderer.cpp, scene_buffers.cpp, frame_buffers.cpp,
// frame_kernels.cpp, dispatch.cpp) share beside renderer.h: host/vk's own.
#pragma once

#include "renderer.h"

#include <cstdint>
#include <vector>

// frame_buffers.cpp: whether the output, pass, accumulation and edge-list buffers are those a
// width x height image needs with the renderer's settings; creates them (refusing an image the
// device cannot hold).
bool outputFits(const Renderer& r, uint32_t width, uint32_t height);
void createOutput(Renderer& r, uint32_t width, uint32_t height);

// scene_buffers.cpp: destroys the scene's images.
void destroyImages(Renderer& r);

// frame_kernels.cpp: writes the tile kernels' words, replacing the buffer when they do not fit;
// the pipeline of `unbudgeted` with the device's loop budget and the passes, created once.
void writeTileOrder(Renderer& r, const std::vector<uint32_t>& words);
CachedPipeline& cachedPipeline(Renderer& r, const KernelKey& unbudgeted);

// dispatch.cpp: binds the pipeline and the descriptor set (`tileOffset`: the dynamic offset of
// BINDING_TILE_ORDER, a tile kernel's tiles) and records the dispatch.
void bindAndDispatch(Renderer& r, VkCommandBuffer cmd, VkPipeline pipeline, uint32_t baseX, uint32_t groupsX,
                     uint32_t groupsY, uint32_t tileOffset = 0);
