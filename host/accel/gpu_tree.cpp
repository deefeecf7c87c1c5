#include "gpu_tree.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

static_assert(kBvhLeafSize == TREE_LEAF_SIZE, "the host's leaves fit the kernel's leaf loop");

namespace {

// The float at or below x, and at or above.
float floatDown(double x) {
  float f = float(x);
  return double(f) > x ? std::nextafter(f, -INFINITY) : f;
}
float floatUp(double x) {
  float f = float(x);
  return double(f) < x ? std::nextafter(f, INFINITY) : f;
}

struct Layout {
  const SphereBvh& tree;
  const std::vector<gpu::Sphere>& packed;  // in the scene's order
  std::vector<gpu::Sphere>& spheres;       // in leaf order
  std::vector<gpu::BvhNode>& nodes;
  std::vector<gpu::BvhNode> boxes;  // per host node: its float box

  // Grows `box` by a packed sphere: its float centre and radius, padded by 2^-16 of its size
  // and distance, far above the rounding of the kernel's sphere test (a few float steps).
  static void growBySphere(gpu::BvhNode& box, const gpu::Sphere& s) {
    const glm::dvec3 c(s.centerRadius);
    const double r = s.centerRadius.w;
    const double extent = r + std::ldexp(glm::length(c) + r, -16);
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = std::min(box.lo[a], floatDown(c[a] - extent));
      box.hi[a] = std::max(box.hi[a], floatUp(c[a] + extent));
    }
  }

  // Every host node's box, children before parents (they follow their parent in the list).
  void computeBoxes() {
    boxes.assign(tree.nodes.size(), gpu::BvhNode{glm::vec3(INFINITY), 0u, glm::vec3(-INFINITY), 0u});
    for (size_t i = tree.nodes.size(); i-- > 0;) {
      const BvhNode& n = tree.nodes[i];
      gpu::BvhNode& box = boxes[i];
      if (n.count > 0) {
        for (uint32_t k = n.index; k < n.index + n.count; ++k) growBySphere(box, packed[tree.order[k]]);
      } else {
        box.lo = glm::min(boxes[i + 1].lo, boxes[n.index].lo);
        box.hi = glm::max(boxes[i + 1].hi, boxes[n.index].hi);
      }
    }
  }

  double distanceToCamera(uint32_t node) const {
    return glm::length((glm::dvec3(boxes[node].lo) + glm::dvec3(boxes[node].hi)) * 0.5);
  }

  // Lays out host node `node` and its subtree from nodes.size(), the nearer child first.
  void emit(uint32_t node) {
    const uint32_t index = uint32_t(nodes.size());
    nodes.push_back(boxes[node]);
    const BvhNode& n = tree.nodes[node];
    if (n.count > 0) {
      nodes[index].spheres = n.count << TREE_LEAF_SHIFT | uint32_t(spheres.size());
      for (uint32_t k = n.index; k < n.index + n.count; ++k) spheres.push_back(packed[tree.order[k]]);
    } else {
      const bool swap = distanceToCamera(n.index) < distanceToCamera(node + 1);
      emit(swap ? n.index : node + 1);
      emit(swap ? node + 1 : n.index);
    }
    nodes[index].next = uint32_t(nodes.size());
  }
};

}  // namespace

void layoutSphereTree(const SphereBvh& tree, std::vector<gpu::Sphere>& spheres, std::vector<gpu::BvhNode>& nodes) {
  const std::vector<gpu::Sphere> packed = std::move(spheres);
  spheres.clear();
  nodes.clear();
  if (tree.nodes.empty()) return;
  spheres.reserve(packed.size());
  nodes.reserve(tree.nodes.size());
  Layout layout{tree, packed, spheres, nodes, {}};
  layout.computeBoxes();
  layout.emit(0);
}
