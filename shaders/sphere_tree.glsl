// Walks of the sphere tree (common.h, BvhNode; laid out by host/accel/gpu_tree.cpp): a ray tests the
// spheres of the leaves whose boxes it enters, not every sphere. The walk needs no stack: it
// enters a box's first child, or skips the subtree to the node's `next`; both move forwards, so
// a walk makes at most one pass per node and always ends. Included by intersect.glsl.

BvhNode treeNodeAt(uint i) {
  if (SPHERE_TREE == SPHERE_TREE_STORAGE) return treeStorage[i];
  return treeBlock[i];
}

// 1 / d, its zero components replaced by a tiny one: the slab distances are then never
// 0 * inf (NaN), and an axis the ray runs along bounds nothing unless the origin is outside it.
vec3 slabInverse(vec3 d) { return 1.0 / mix(d, vec3(1.0e-30), equal(d, vec3(0.0))); }

// Whether the ray enters the node's box at some t in [0, tMax]. The distances are widened by far
// more than their rounding (a few float steps), so that a sphere the ray hits is never skipped.
bool entersBox(BvhNode n, vec3 o, vec3 inverse, float tMax) {
  const float widen = 1.0 / 1048576.0;
  vec3 t0 = (n.lo - o) * inverse, t1 = (n.hi - o) * inverse;
  vec3 near = min(t0, t1), far = max(t0, t1);
  float enter = max(max(near.x, near.y), max(near.z, 0.0));
  float leave = min(min(far.x, far.y), far.z);
  return enter - enter * widen <= min(leave + abs(leave) * widen, tMax);
}

uint leafCount(BvhNode n) { return n.spheres >> TREE_LEAF_SHIFT; }
uint leafFirst(BvhNode n) { return n.spheres & ((1u << TREE_LEAF_SHIFT) - 1u); }

// The closest sphere hit nearer than hit.t, into hit.
void closestSphereInTree(vec3 o, vec3 d, inout Hit hit) {
  vec3 inverse = slabInverse(d);
  uint node = 0u, passes = 0u;
  // A do-while: lavapipe leaves a loop only when no lane is left, and a for loop's test at
  // the top adds one pass with every lane masked off (the tree has a node: it has spheres).
  do {
    ++passes;
    BvhNode n = treeNodeAt(node);
    bool enters = entersBox(n, o, inverse, hit.t);
    uint count = leafCount(n);
    if (enters && count > 0u) {
      uint first = leafFirst(n);
      for (uint k = 0u; k < TREE_LEAF_SIZE; ++k) {
        if (k < count) {
          vec4 centerRadius = sphereAt(first + k).centerRadius;
          notePrimarySphere(o, d, centerRadius, first + k, hit.t);
          float t = intersectSphere(o, d, centerRadius, 0.0, hit.t);
          if (t > 0.0) hit = Hit(t, HIT_SPHERE, first + k);
        }
      }
    }
    node = enters && count == 0u ? node + 1u : n.next;
  } while (node < frame.treeNodeCount);
  countLoop(passes);
}

// True if a sphere lies on the segment from o along unit d before distance tMax.
bool occludedInTree(vec3 o, vec3 d, float tMax) {
  vec3 inverse = slabInverse(d);
  uint node = 0u;
  uint passes = 0u;
  bool blocked = false;
  do {
    ++passes;
    BvhNode n = treeNodeAt(node);
    bool enters = entersBox(n, o, inverse, tMax);
    uint count = leafCount(n);
    if (enters && count > 0u) {
      uint first = leafFirst(n);
      for (uint k = 0u; k < TREE_LEAF_SIZE; ++k) {
        if (k < count) {
          vec4 centerRadius = sphereAt(first + k).centerRadius;
          noteShadowSphere(o, d, centerRadius);
          if (intersectSphere(o, d, centerRadius, 0.0, tMax) > 0.0) blocked = true;
        }
      }
    }
    node = blocked ? frame.treeNodeCount : (enters && count == 0u ? node + 1u : n.next);
  } while (node < frame.treeNodeCount);
  countLoop(passes);
  return blocked;
}

// The closest sphere hit of a primary ray nearer than hit.t, into hit: the spheres listed for
// its tile (host/accel/tile_lists.h; the lanes of a workgroup share one tile, so the list's loads and
// its loop are the same for all of them), or the tree's where the tile's list is long. The list
// runs nearest first, so a ray stops at a sphere whose nearest point lies beyond its hit (the
// floor's, or a sphere's): no later one can be nearer. The margin of 2^-10 is far beyond the
// float rounding of the distance and of the sphere test.
void closestSphereInTile(vec3 o, vec3 d, inout Hit hit) {
  uint first = tileRanges[2u * primaryTile], count = tileRanges[2u * primaryTile + 1u];
  if (count == TILE_USE_TREE) {
    closestSphereInTree(o, d, hit);
    return;
  }
  uint passes = 0u;
  for (uint k = 0u; k < count; ++k) {
    ++passes;
    uint i = tileSpheres[first + k];
    vec4 centerRadius = sphereAt(i).centerRadius;
    if (length(centerRadius.xyz - o) - centerRadius.w > hit.t * (1.0 + 1.0 / 1024.0)) break;
    notePrimarySphere(o, d, centerRadius, i, hit.t);
    float t = intersectSphere(o, d, centerRadius, 0.0, hit.t);
    if (t > 0.0) hit = Hit(t, HIT_SPHERE, i);
  }
  countLoop(passes);
}

// The range of spheres listed for the cell of the light's shadow grid (host/accel/shadow_grid.h)
// where the line from the light through o meets the grid's plane, if o lies between the plane
// and half the light's height above it (the point on the plane then lies no farther from o than
// the light does); left as it is where the light has no grid or o lies elsewhere. Past the
// grid's edge no shadow falls: an empty range.
void shadowGridRange(vec3 o, vec3 d, float tMax, uint light, inout uint first, inout uint count) {
  ShadowGrid grid = frame.shadowGrids[light];
  if (grid.rows == TILE_USE_TREE) return;
  Plane p = planeAt(grid.plane);
  float height = dot(p.normalDistance.xyz, o) - p.normalDistance.w, rise = dot(p.normalDistance.xyz, d);
  if (!(height >= 0.0 && rise > 0.0 && height <= rise * tMax)) return;
  vec3 q = o - d * (height / rise);
  vec2 cell = (vec2(dot(q, p.tangentScale.xyz), dot(q, p.binormal.xyz)) - grid.corner.xy) * grid.corner.z;
  count = 0u;
  if (!(cell.x >= 0.0 && cell.y >= 0.0 && cell.x < float(grid.columns) && cell.y < float(grid.rows))) return;
  uint range = grid.firstRange + 2u * (uint(cell.y) * grid.columns + uint(cell.x));
  first = tileRanges[range];
  count = tileRanges[range + 1u];
}

// True if one of the `count` spheres listed from `first` lies on the segment from o along unit
// d before distance tMax.
bool occludedInList(uint first, uint count, vec3 o, vec3 d, float tMax) {
  uint passes = 0u;
  bool blocked = false;
  for (uint k = 0u; k < count; ++k) {
    ++passes;
    vec4 centerRadius = sphereAt(tileSpheres[first + k]).centerRadius;
    noteShadowSphere(o, d, centerRadius);
    if (intersectSphere(o, d, centerRadius, 0.0, tMax) > 0.0) {
      blocked = true;
      break;
    }
  }
  countLoop(passes);
  return blocked;
}

// True if a sphere listed for the light's shadow grid where the ray lands lies on the segment
// from o along unit d before distance tMax, or one of the tree's where the grid does not reach.
bool occludedInGrid(vec3 o, vec3 d, float tMax, uint light) {
  uint first = 0u, count = TILE_USE_TREE;
  shadowGridRange(o, d, tMax, light, first, count);
  if (count == TILE_USE_TREE) return occludedInTree(o, d, tMax);
  return occludedInList(first, count, o, d, tMax);
}

// True if a sphere listed for the ray's cell of tiles and light (host/accel/shadow_lists.h: every
// sphere that can lie between the light and a point the cell sees; the lanes of a workgroup
// share the list) lies on the segment from o along unit d before distance tMax. Where the list
// is long, the spheres of the light's shadow grid where the ray lands, in kernels whose spheres
// are in storage buffers (lavapipe runs all of a kernel's code, and in smaller scenes the
// grid costs more than it saves: docs/performance.md, "Shadow grids"), or the tree's.
bool occludedInTile(vec3 o, vec3 d, float tMax, uint light) {
  uint range = frame.shadowRanges + 2u * (shadowCell * lightCount() + light);
  uint first = tileRanges[range], count = tileRanges[range + 1u];
  if (count == TILE_USE_TREE) {
    if (SPHERE_TREE == SPHERE_TREE_STORAGE) return occludedInGrid(o, d, tMax, light);
    return occludedInTree(o, d, tMax);
  }
  return occludedInList(first, count, o, d, tMax);
}
