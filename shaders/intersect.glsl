// Ray/sphere and ray/plane intersection, closest hit and shadow queries.
// Comparisons are written so that NaN counts as a miss: !(t > tMin && t < tMax).

const float T_MAX = 3.0e38;

struct Hit {
  float t;
  uint kind;   // HIT_*
  uint index;  // of the sphere or plane (sphereAt, planeAt)
};

// Smallest root t in (tMin, tMax) of |o + t d - c| = r for unit d, or -1.
// Stable form (Ray Tracing Gems ch. 7): the discriminant from the perpendicular
// distance, and the second root from c/q to avoid cancellation.
float intersectSphere(vec3 o, vec3 d, vec4 centerRadius, float tMin, float tMax) {
  vec3 f = o - centerRadius.xyz;
  float r = centerRadius.w;
  float b = -dot(f, d);
  vec3 perp = f + b * d;
  float disc = r * r - dot(perp, perp);
  if (!(disc >= 0.0)) return -1.0;
  float c = dot(f, f) - r * r;
  float q = b + (b >= 0.0 ? sqrt(disc) : -sqrt(disc));
  float t0 = c / q;
  float t1 = q;
  float near = min(t0, t1), far = max(t0, t1);
  if (near > tMin && near < tMax) return near;
  if (far > tMin && far < tMax) return far;  // origin inside the sphere
  return -1.0;
}

// t of x.n = d along the ray, or -1 (parallel rays give inf or NaN: a miss).
float intersectPlane(vec3 o, vec3 dir, vec4 normalDistance, float tMin, float tMax) {
  float t = (normalDistance.w - dot(normalDistance.xyz, o)) / dot(normalDistance.xyz, dir);
  return (t > tMin && t < tMax) ? t : -1.0;
}

#include "edge_flags.glsl"

// The tree's walks and the tile and shadow lists, only in the modules for scenes with a tree
// (RAYTEX_SPHERE_TREE, CMakeLists.txt): the driver processes a module's every function before
// the specialisation constants drop what a scene lacks.
#ifdef RAYTEX_SPHERE_TREE
#include "sphere_tree.glsl"
#endif

// The closest hit of a primary ray. With a sphere tree the planes come first: their nearest hit bounds the
// boxes the walk enters (a floor hides the spheres beyond it). Loops bounded by Frame's counts
// count their passes (loop_budget.glsl); those over constants are unrolled.
Hit closestHit(vec3 o, vec3 d) {
  Hit hit = Hit(T_MAX, HIT_NONE, 0u);
  if (SPHERE_TREE == SPHERE_TREE_NONE) {
    for (uint i = 0u; i < sphereCount(); ++i) {
      vec4 centerRadius = sphereAt(i).centerRadius;
      notePrimarySphere(o, d, centerRadius, i, hit.t);
      float t = intersectSphere(o, d, centerRadius, 0.0, hit.t);
      if (t > 0.0) hit = Hit(t, HIT_SPHERE, i);
    }
    if (SPHERE_COUNT == COUNT_FROM_FRAME) countLoop(sphereCount());
  }
  for (uint i = 0u; i < planeCount(); ++i) {
    vec4 normalDistance = planeAt(i).normalDistance;
    notePrimaryPlane(o, d, normalDistance, i);
    float t = intersectPlane(o, d, normalDistance, 0.0, hit.t);
    if (t > 0.0) hit = Hit(t, HIT_PLANE, i);
  }
  if (PLANE_COUNT == COUNT_FROM_FRAME) countLoop(planeCount());
#ifdef RAYTEX_SPHERE_TREE
  if (SPHERE_TREE != SPHERE_TREE_NONE) {
    if (TILE_LISTS) closestSphereInTile(o, d, hit);
    else closestSphereInTree(o, d, hit);
  }
#endif
  return hit;
}

// True if anything lies on the segment from o along unit d before distance tMax, a shadow ray
// to light `light` (its cell's list of spheres: SHADOW_LISTS). `passes`: the
// loops' passes for the caller to count (loop_budget.glsl) where the lanes meet again: a lane
// that returns early passed no later loop, so the busiest lane's sum is the group's.
bool occluded(vec3 o, vec3 d, float tMax, uint light, out uint passes) {
  passes = 1u;  // a masked pass of the second loop (countLoop adds one)
  for (uint i = 0u; SPHERE_TREE == SPHERE_TREE_NONE && i < sphereCount(); ++i) {
    ++passes;
    vec4 centerRadius = sphereAt(i).centerRadius;
    noteShadowSphere(o, d, centerRadius);
    if (intersectSphere(o, d, centerRadius, 0.0, tMax) > 0.0) return true;
  }
  for (uint i = 0u; i < planeCount(); ++i) {
    ++passes;
    if (intersectPlane(o, d, planeAt(i).normalDistance, 0.0, tMax) > 0.0) return true;
  }
#ifdef RAYTEX_SPHERE_TREE
  if (SPHERE_TREE != SPHERE_TREE_NONE) return SHADOW_LISTS ? occludedInTile(o, d, tMax, light) : occludedInTree(o, d, tMax);
#endif
  return false;
}
