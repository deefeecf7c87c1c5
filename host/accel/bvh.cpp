#include "bvh.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace {

constexpr int kBins = 16;

struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  void grow(glm::dvec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  double halfArea() const {
    if (!(hi.x >= lo.x)) return 0.0;
    glm::dvec3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

struct Builder {
  const std::vector<Sphere>& spheres;
  SphereBvh& bvh;

  Box sphereBox(uint32_t i) const {
    const glm::dvec3 c(spheres[i].center);
    const double r = spheres[i].radius;
    Box b;
    b.lo = c - r;
    b.hi = c + r;
    return b;
  }
  glm::dvec3 centre(uint32_t i) const { return glm::dvec3(spheres[i].center); }

  // The split of order[begin, end) along the centres' longest axis at the bin boundary of least
  // SAH cost; returns the first index of the second part, or begin when the centres coincide.
  uint32_t sahSplit(uint32_t begin, uint32_t end) {
    Box centres;
    for (uint32_t k = begin; k < end; ++k) centres.grow(centre(bvh.order[k]));
    const glm::dvec3 extent = centres.hi - centres.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (!(extent[axis] > 0.0)) return begin;  // every centre at one point
    const double scale = kBins / extent[axis];
    auto binOf = [&](uint32_t i) {
      return std::min(kBins - 1, int((centre(i)[axis] - centres.lo[axis]) * scale));
    };
    std::array<Box, kBins> boxes;
    std::array<uint32_t, kBins> counts{};
    for (uint32_t k = begin; k < end; ++k) {
      const int b = binOf(bvh.order[k]);
      boxes[b].grow(sphereBox(bvh.order[k]));
      ++counts[b];
    }
    // Costs of the splits after bin s, from the left and right sweeps.
    std::array<double, kBins - 1> cost{};
    Box left, right;
    uint32_t nLeft = 0, nRight = 0;
    for (int s = 0; s < kBins - 1; ++s) {
      left.grow(boxes[s]);
      nLeft += counts[s];
      cost[s] = left.halfArea() * nLeft;
    }
    for (int s = kBins - 1; s > 0; --s) {
      right.grow(boxes[s]);
      nRight += counts[s];
      cost[s - 1] += right.halfArea() * nRight;
    }
    const int best = int(std::min_element(cost.begin(), cost.end()) - cost.begin());
    auto middle = std::partition(bvh.order.begin() + begin, bvh.order.begin() + end,
                                 [&](uint32_t i) { return binOf(i) <= best; });
    const uint32_t split = uint32_t(middle - bvh.order.begin());
    return split == begin || split == end ? begin : split;
  }

  void build(uint32_t begin, uint32_t end) {
    const uint32_t node = uint32_t(bvh.nodes.size());
    bvh.nodes.emplace_back();
    Box bounds;
    for (uint32_t k = begin; k < end; ++k) bounds.grow(sphereBox(bvh.order[k]));
    // Padded outward by a relative margin, so that rounding in the slab test cannot lose a
    // sphere that the ray touches at its box's surface.
    const glm::dvec3 pad = 1e-9 * (glm::abs(bounds.lo) + glm::abs(bounds.hi) + (bounds.hi - bounds.lo)) + 1e-300;
    bvh.nodes[node].lo = bounds.lo - pad;
    bvh.nodes[node].hi = bounds.hi + pad;
    uint32_t split = end - begin > kBvhLeafSize ? sahSplit(begin, end) : begin;
    if (split == begin && end - begin > kBvhLeafSize) split = begin + (end - begin) / 2;  // by index
    if (split == begin) {
      bvh.nodes[node].count = end - begin;
      bvh.nodes[node].index = begin;
      return;
    }
    build(begin, split);
    bvh.nodes[node].index = uint32_t(bvh.nodes.size());
    build(split, end);
  }
};

// Where the ray enters and leaves the box (tEnter > tLeave: it misses). fmin/fmax drop the NaN
// of a zero direction component on a slab's plane (0 * inf), which leaves that axis unbounded.
void slab(const BvhNode& n, glm::dvec3 o, glm::dvec3 inv, double& tEnter, double& tLeave) {
  tEnter = 0.0;
  tLeave = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double t0 = (n.lo[a] - o[a]) * inv[a], t1 = (n.hi[a] - o[a]) * inv[a];
    tEnter = std::fmax(tEnter, std::fmin(t0, t1));
    tLeave = std::fmin(tLeave, std::fmax(t0, t1));
  }
}

}  // namespace

SphereBvh buildSphereBvh(const std::vector<Sphere>& spheres) {
  SphereBvh bvh;
  if (spheres.empty()) return bvh;
  bvh.order.resize(spheres.size());
  for (uint32_t i = 0; i < bvh.order.size(); ++i) bvh.order[i] = i;
  bvh.nodes.reserve(2 * spheres.size());
  Builder{spheres, bvh}.build(0, uint32_t(spheres.size()));
  return bvh;
}

void visitSpheresAlong(const SphereBvh& bvh, glm::dvec3 o, glm::dvec3 d, const double& tMax,
                       const std::function<void(uint32_t)>& visit) {
  if (bvh.nodes.empty()) return;
  const glm::dvec3 inv = 1.0 / d;
  struct Entry {
    uint32_t node;
    double tEnter;
  };
  // Reused by each thread's rays: one allocation per thread, not per ray.
  thread_local std::vector<Entry> stack;
  stack.clear();
  auto push = [&](uint32_t node) {
    double tEnter, tLeave;
    slab(bvh.nodes[node], o, inv, tEnter, tLeave);
    if (tEnter <= tLeave && tEnter <= tMax) stack.push_back({node, tEnter});
  };
  push(0);
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    if (e.tEnter > tMax) continue;  // a hit found since it was pushed lies nearer
    const BvhNode& n = bvh.nodes[e.node];
    if (n.count > 0) {
      for (uint32_t k = n.index; k < n.index + n.count; ++k) visit(bvh.order[k]);
      continue;
    }
    // The nearer child on top of the stack, so a close hit prunes the farther one.
    const size_t before = stack.size();
    push(e.node + 1);
    push(n.index);
    if (stack.size() == before + 2 && stack[before].tEnter < stack[before + 1].tEnter)
      std::swap(stack[before], stack[before + 1]);
  }
}
