// Per light, a grid over a plane that lists the spheres whose shadow (plane_shadow.h) covers
// each of its cells: the spheres a shadow ray may meet, for rays whose cell of screen has a
// long list (shadow_lists.h). A sphere between a point q and the light also lies between the
// light and the point q' where the line from the light through q meets the plane, so it is
// listed for the grid cell of q' (shaders/sphere_tree.glsl, shadowGridRange). That holds for
// every q between the plane and the light, on any object: at the far end of a field of small
// spheres, where a cell of screen sees hundreds of them, a ray tests the few whose shadows
// fall where it would land. Built on the host for each camera from the values the kernel uses,
// the shadows padded far beyond the kernel's float rounding. No Vulkan.
#pragma once

#include "common.h"
#include "tile_lists.h"

#include <vector>

// A light without a grid (its rays walk the tree where their cell's list is long).
inline gpu::ShadowGrid noShadowGrid() { return gpu::ShadowGrid{0, 0, TILE_USE_TREE, 0, {}}; }

// Sets lists.shadowGrids, a grid per light (common.h, ShadowGrid), its cell ranges appended to
// lists.ranges and its entries to lists.spheres. A light gets none (rows TILE_USE_TREE) where
// every cell's list is short, where no plane lies below it with every sphere's shadow on it
// bounded (a sphere reaching the light's height), or where the shadows would cover more than
// TILE_FILL_LIMIT grid cells a sphere on average.
void appendShadowGrids(const std::vector<gpu::Sphere>& spheres, const std::vector<gpu::Plane>& planes,
                       const std::vector<gpu::Light>& lights, TileLists& lists);
