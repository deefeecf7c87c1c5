// Per-tile lists of the spheres a primary ray may hit (shaders/sphere_tree.glsl,
// closestSphereInTile): the image in tiles of TILE_SIZE x TILE_SIZE pixels (a workgroup each),
// every sphere in the tiles its conservative screen bounds touch. A primary ray then tests its
// tile's few spheres instead of walking the tree. Built on the host for each camera and size
// from the values the kernel uses. No Vulkan.
#pragma once

#include "common.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

struct TileLists {
  uint32_t columns = 0, rows = 0;
  // Per tile, row-major: its first entry of `spheres` and its count (two words), or the count
  // TILE_USE_TREE: more than TILE_LIST_MAX spheres, its rays walk the tree. Where the scene has
  // shadow lists (shadow_lists.h), their ranges follow from word shadowRanges on, per cell of
  // SHADOW_CELL x SHADOW_CELL tiles (shadowColumns a row) and light, and their entries follow
  // the primary ones in `spheres`.
  std::vector<uint32_t> ranges;
  std::vector<uint32_t> spheres;  // indices into the packed spheres, each once in a list
  uint32_t shadowRanges = 0;      // the first word of the shadow lists' ranges (0: none)
  uint32_t shadowColumns = 0, shadowRows = 0;
  std::vector<gpu::ShadowGrid> shadowGrids;  // per light (shadow_grid.h); empty: none
};

struct TileRect {
  uint32_t x0 = 1, y0 = 1, x1 = 0, y1 = 0;  // tiles [x0, x1] x [y0, y1]; none by default
  bool empty() const { return x1 < x0 || y1 < y0; }
  uint64_t area() const { return empty() ? 0 : uint64_t(x1 - x0 + 1) * (y1 - y0 + 1); }
};

// The inward normals of the four sides of the camera's view (planes through the eye), widened
// by two pixels: a point p is in the view where dot(side, p) >= 0 for all four.
struct ViewSides {
  glm::dvec3 inward[4];
};
ViewSides viewSides(const gpu::Frame& frame);

// The eight corners of the cube of half side r around c (a sphere's bounding cube).
void boundingCubeCorners(const glm::dvec3& c, double r, glm::dvec3 (&corners)[8]);

// The tiles that the film positions of camera-relative `points` touch, their bounds grown by a
// pixel; every tile if a point is not in front of the camera, none if all lie off screen.
TileRect tilesOfPoints(const gpu::Frame& frame, const glm::dvec3* points, size_t count, uint32_t columns, uint32_t rows);

// The indices of `spheres` (camera-relative) by the distance of their nearest point from the
// camera, ascending; equal distances keep the scene's order, as the loop over every sphere does.
std::vector<uint32_t> nearestFirst(const std::vector<gpu::Sphere>& spheres);

// The lists for `spheres` (camera-relative, as packed) seen through `frame` (its camera axes,
// width and height), each nearest first (nearestFirst). A sphere that reaches the camera plane
// is in every tile. Where the lists would be long to build (the spheres' screen bounds cover
// more than TILE_FILL_LIMIT entries a tile in all), every tile walks the tree: the host's work
// stays within O(spheres + tiles).
TileLists buildTileLists(const gpu::Frame& frame, const std::vector<gpu::Sphere>& spheres);
