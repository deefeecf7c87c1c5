// The kernel plan: which kernels render a frame and how its samples are dispatched. The one home
// of raytex's lavapipe-only machinery, which headless renders, the viewer and the benchmarks all
// go through:
// - tile kernels (tile_kernels.h): a frame as up to MAX_TILE_KERNELS kernels, each specialised to
//   the texture kinds its tiles can show, where they pay for their pipelines;
// - samples one dispatch each where together they would pass the driver's loop limit.
// On any other driver a frame is one kernel specialised to the scene, its samples in one dispatch.
// (The kernel built around the scene's values, KernelOptions::bakeValues, serves every driver.)
#pragma once

#include "gpu_scene.h"
#include "kernel_key.h"
#include "renderer.h"
#include "scene.h"
#include "render_options.h"

#include <vector>

// Whether the job's samples go one dispatch each: where together they would pass lavapipe's loop
// limit (kMaxLoopIterations), the progressive kernel adds them one at a time, the same image bit
// for bit. A sphere tree's walks are not known before they run: its samples always go one at a
// time. With passes the kernel traces the pixel centre once more. The coverage filter's samples
// always go one at a time: each one's edge pass follows its main kernel (coverage.glsl).
bool samplesPerDispatch(const Renderer& renderer, const Scene& scene, const GpuScene& gpuScene, const RenderJob& job);

// Makes `key`'s kernel render the frame, or on lavapipe, with the image in one band, tile kernels
// where they pay within `samples` samples of every pixel (frames times samples per pixel;
// INFINITY: the steady frame, as a benchmark or a long render gets).
void prepareFrameKernels(Renderer& renderer, const GpuScene& gpuScene, const KernelKey& key, double samples);

// The viewer's kernels for `key`: on lavapipe, where a tile that no sphere reaches saves
// (sphereFreeTilesSave), the tile kernels of the planes' kinds alone and of all, whatever the
// camera; else `key` alone. The keys, to compile ahead (viewerFrameKernels), and made current
// over the tiles of the camera as packed (prepareViewerFrameKernels).
std::vector<KernelKey> viewerFrameKernels(const Renderer& renderer, const KernelKey& key);
void prepareViewerFrameKernels(Renderer& renderer, const GpuScene& packed, const KernelKey& key);
