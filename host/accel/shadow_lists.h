// Lists of the spheres a shadow ray may meet (shaders/sphere_tree.glsl, occludedInTile), per
// cell of SHADOW_CELL x SHADOW_CELL tiles and light: every sphere that can lie between the light
// and a point the cell's pixels see, so that a shadow ray tests a few spheres the whole
// workgroup shares instead of walking the tree. A point seen in a cell lies on a plane or on a
// sphere of one of its tiles' primary lists, and a sphere B can hide the light from it only if
// - on a plane: the point lies in B's shadow on that plane (B projected from the light), so B
//   goes to the cells that shadow covers on screen;
// - on a sphere A: B touches the cone from the light around A, so B goes to the cells whose
//   tiles list A.
// Built on the host for each camera from the values the kernel uses, every bound padded far
// beyond the kernel's float rounding; a cell whose list would be long, or one of whose tiles'
// primary rays walk the tree, walks the tree for its shadow rays too. Cells, not tiles: a
// quarter of the lists to build on each camera move (docs/performance.md). No Vulkan.
#pragma once

#include "common.h"
#include "tile_lists.h"

#include <cstddef>
#include <vector>

// Whether a scene of `lights` lights and `planes` planes gets shadow lists (SPEC_SHADOW_LISTS)
// where its spheres walk a tree: at least one light, at most SHADOW_LIST_MAX_LIGHTS and
// SHADOW_LIST_MAX_PLANES.
bool shadowListsFit(size_t lights, size_t planes);

// Appends the shadow lists of every cell and light to `lists` (built by buildTileLists for the
// same frame and spheres): their ranges from word lists.shadowRanges on, per cell (row-major,
// lists.shadowColumns a row) and light, two words each as the primary ones. `nodes`: the
// sphere tree as laid out for the camera (gpu_tree.h), over `spheres` in its leaf order. Where
// a light's lists would hold more than TILE_FILL_LIMIT entries a cell on average, every cell
// walks the tree for that light.
void appendShadowLists(const gpu::Frame& frame, const std::vector<gpu::Sphere>& spheres,
                       const std::vector<gpu::Plane>& planes, const std::vector<gpu::Light>& lights,
                       const std::vector<gpu::BvhNode>& nodes, TileLists& lists);
