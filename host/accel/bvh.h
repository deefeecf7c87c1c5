// A bounding volume hierarchy over a scene's spheres, built on the host in double precision
// with binned surface-area-heuristic splits, and a traversal that visits the spheres whose
// boxes a ray enters, nearest box first. No Vulkan: the CPU paths (ray counting) use it.
#pragma once

#include "scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <vector>

struct BvhNode {
  glm::dvec3 lo{0.0}, hi{0.0};  // the box of every sphere below, padded outward
  uint32_t count = 0;           // spheres in a leaf; 0 for an inner node
  uint32_t index = 0;           // a leaf's first entry of SphereBvh::order; an inner node's
                                // second child (its first is the next node)
};

struct SphereBvh {
  std::vector<BvhNode> nodes;   // depth first, the root at 0; empty without spheres
  std::vector<uint32_t> order;  // sphere indices, each leaf's a contiguous run
};

// At most kBvhLeafSize spheres in a leaf (those whose centres no split tells apart are split by
// their order). One: on lavapipe a leaf's spheres cost more than another node's pass
// (docs/performance.md, "One sphere a leaf").
constexpr uint32_t kBvhLeafSize = 1;

SphereBvh buildSphereBvh(const std::vector<Sphere>& spheres);

// Calls visit(i) for every sphere i whose box the ray o + t d, 0 < t <= tMax, enters, skipping
// boxes entered beyond tMax; tMax may shrink during the walk (the closest hit so far). Every
// sphere the ray hits at some t in (0, tMax] is visited.
void visitSpheresAlong(const SphereBvh& bvh, glm::dvec3 o, glm::dvec3 d, const double& tMax,
                       const std::function<void(uint32_t)>& visit);
