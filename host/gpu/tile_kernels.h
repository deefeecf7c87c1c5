// Tile kernels: one frame dispatched as a few kernels, each over its own tiles of the image and
// specialised to the texture kinds those tiles can show. On lavapipe a SIMD group runs every
// case of the texture dispatch that the kernel holds, masked, whatever its lanes hit, so the
// kinds of the whole scene cost every pixel; a tile whose objects carry no noise kind then runs
// no noise code. Which tiles can show what comes from the per-tile sphere lists (tile_lists.h);
// every plane counts in every tile. No Vulkan.
#pragma once

#include "common.h"
#include "kernel_key.h"

#include <cstdint>
#include <vector>

struct GpuScene;

// What reading the tile from the order costs a tile kernel's pixel against the one kernel's, in
// x86 instructions per pixel (the default scene's 1080p frame on lavapipe, one kernel through
// the tile order against none: docs/performance.md, "Tile kernels").
constexpr double kTileOrderCost = 10.0;

// Texture kinds (bit 1 << TEX_*) per shape: what a kernel is specialised to.
struct TextureKinds {
  uint32_t sphere = 0, plane = 0;
  bool covers(const TextureKinds& o) const { return (o.sphere & ~sphere) == 0 && (o.plane & ~plane) == 0; }
  bool operator==(const TextureKinds& o) const { return sphere == o.sphere && plane == o.plane; }
  bool operator<(const TextureKinds& o) const { return sphere != o.sphere ? sphere < o.sphere : plane < o.plane; }
};

// One kernel of a frame: its kinds and its tiles, each as column | row << 16 (the words of
// BINDING_TILE_ORDER).
struct TileKernel {
  TextureKinds kinds;
  std::vector<uint32_t> tiles;
};

// A frame's kernels; none: the one kernel over the whole image.
struct TilePlan {
  std::vector<TileKernel> kernels;
  // Per frame against the one kernel (x86 instructions, estimated, less kTileOrderCost a pixel).
  double savedInstructions = 0;
};

// Per tile (row-major, as gpuScene.tiles) the kinds its primary rays can show: every plane's and
// those of the spheres listed for it (every sphere's where it walks the tree). Empty without
// tile lists.
std::vector<TextureKinds> tileKinds(const GpuScene& gpuScene);

// Estimated x86 instructions per pixel that a kernel holding `kinds` spends on their code
// (TextureKindInfo::kernelCost, measured on lavapipe).
double kindsCost(const TextureKinds& kinds);

// At most MAX_TILE_KERNELS kind sets for a frame: `all` (every tile fits it), then, one at a
// time, the tiles' own set that saves the most, while one saves anything.
std::vector<TextureKinds> chooseTileKernels(const std::vector<TextureKinds>& tiles, const TextureKinds& all);

// The sets the viewer keeps while its camera moves: the planes' kinds alone (the tiles no
// sphere reaches) and `all`. A camera move then never needs a kernel not prepared before.
std::vector<TextureKinds> sphereFreeTileKernels(const TextureKinds& all);

// Whether a tile that no sphere reaches saves more with the planes' kinds alone than the tile
// order costs: the viewer's choice, the same for any camera.
bool sphereFreeTilesSave(const TextureKinds& all);

// Each tile to the cheapest of `family` that covers it (family[0] must cover every tile); the
// kernels that get no tile are left out (no kernel at all without tiles).
TilePlan assignTiles(const std::vector<TextureKinds>& family, const std::vector<TextureKinds>& tiles, uint32_t columns);

// `key` as the tile kernel for `kinds`.
KernelKey tileKernelKey(KernelKey key, const TextureKinds& kinds);

// The plan for `gpuScene` as packed for its camera, from chooseTileKernels' sets.
TilePlan planTileKernels(const GpuScene& gpuScene, const TextureKinds& all);

// Whether a plan's kernels pay for the pipelines they add to the one kernel's, on lavapipe, within
// `samples` samples of every pixel (frames times samples per pixel; INFINITY: the steady frame):
// the estimated time saved against their creation (measured: docs/performance.md, "Tile kernels").
bool tileKernelsPay(const TilePlan& plan, double samples);
