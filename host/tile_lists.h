// Per-tile lists of the spheres a primary ray may hit (shaders/sphere_tree.glsl,
// closestSphereInTile): the image in tiles of TILE_SIZE x TILE_SIZE pixels (a workgroup each),
// every sphere in the tiles its conservative screen bounds touch. A primary ray then tests its
// tile's few spheres instead of walking the tree. Built on the host for each camera and size
// from the values the kernel uses. No Vulkan.
#pragma once

#include "common.h"

#include <cstdint>
#include <vector>

struct TileLists {
  uint32_t columns = 0, rows = 0;
  // Per tile, row-major: its first entry of `spheres` and its count (two words), or the count
  // TILE_USE_TREE: more than TILE_LIST_MAX spheres, its rays walk the tree.
  std::vector<uint32_t> ranges;
  std::vector<uint32_t> spheres;  // indices into the packed spheres, ascending within a tile
};

// The lists for `spheres` (camera-relative, as packed) seen through `frame` (its camera axes,
// width and height). A sphere that reaches the camera plane is in every tile. Where the lists
// would be long to build (the spheres' screen bounds cover more than TILE_FILL_LIMIT entries a
// tile in all), every tile walks the tree: the host's work stays within O(spheres + tiles).
TileLists buildTileLists(const gpu::Frame& frame, const std::vector<gpu::Sphere>& spheres);
