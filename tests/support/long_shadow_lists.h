// Test scenes' lists with every cell's shadow list marked long, so that each shadow ray between
// a grid's plane and its light looks its grid up (host/accel/shadow_grid.h), and the others walk the
// tree: the lists built as packCamera builds them, the grids after the marking.
#pragma once

#include "gpu_scene.h"
#include "shadow_grid.h"
#include "shadow_lists.h"

inline void markShadowListsLong(GpuScene& g) {
  g.tiles = buildTileLists(g.frame, g.spheres);
  appendShadowLists(g.frame, g.spheres, g.planes, g.lights, g.treeNodes, g.tiles);
  for (size_t t = g.tiles.shadowRanges + 1; t < g.tiles.ranges.size(); t += 2) g.tiles.ranges[t] = TILE_USE_TREE;
  appendShadowGrids(g.spheres, g.planes, g.lights, g.tiles);
  for (size_t l = 0; l < g.tiles.shadowGrids.size(); ++l) g.frame.shadowGrids[l] = g.tiles.shadowGrids[l];
}
