// The sphere BVH: its structure, and closest hits through it against testing every sphere
// (no device).
#include "bvh.h"
#include "gpu_scene.h"
#include "gpu_tree.h"
#include "tile_lists.h"
#include "reference.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

Scene randomSpheres(int n, double side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(-0.5 * side, 0.5 * side), radius(0.05, 0.6);
  Scene scene;
  for (int i = 0; i < n; ++i) {
    Sphere s;
    s.center = {position(rng), position(rng), position(rng)};
    s.radius = radius(rng);
    scene.spheres.push_back(s);
  }
  return scene;
}

bool contains(const BvhNode& node, const Sphere& s) {
  for (int a = 0; a < 3; ++a)
    if (s.center[a] - s.radius < node.lo[a] || s.center[a] + s.radius > node.hi[a]) return false;
  return true;
}

// Walks the tree from `node`, checking that every box holds what lies below it; returns the
// spheres below, in order.
std::vector<uint32_t> spheresBelow(const SphereBvh& bvh, const Scene& scene, uint32_t node) {
  const BvhNode& n = bvh.nodes[node];
  std::vector<uint32_t> below;
  if (n.count > 0) {
    below.assign(bvh.order.begin() + n.index, bvh.order.begin() + n.index + n.count);
  } else {
    EXPECT_GT(n.index, node + 1);
    below = spheresBelow(bvh, scene, node + 1);
    std::vector<uint32_t> second = spheresBelow(bvh, scene, n.index);
    below.insert(below.end(), second.begin(), second.end());
  }
  for (uint32_t i : below) EXPECT_TRUE(contains(n, scene.spheres[i])) << "node " << node << ", sphere " << i;
  return below;
}

// Closest hits through the BVH and without it, for rays from inside and outside the cloud in
// every direction, some along the axes (direction components of 0).
void expectSameHits(const Scene& scene, double side, unsigned seed) {
  const SphereBvh bvh = buildSphereBvh(scene.spheres);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(-side, side), component(-1.0, 1.0);
  for (int r = 0; r < 3000; ++r) {
    const glm::dvec3 o(position(rng), position(rng), position(rng));
    glm::dvec3 d(component(rng), component(rng), component(rng));
    if (r % 10 == 0) d = glm::dvec3(0.0);
    if (r % 10 == 0) d[r % 3] = r % 20 == 0 ? 1.0 : -1.0;
    if (glm::dot(d, d) == 0.0) continue;
    d = glm::normalize(d);
    const ReferenceHit all = referenceClosestHit(scene, o, d, false);
    const ReferenceHit fast = referenceClosestHit(scene, o, d, false, &bvh);
    ASSERT_EQ(fast.kind, all.kind) << "ray " << r;
    ASSERT_EQ(fast.index, all.index) << "ray " << r;
    ASSERT_EQ(fast.t, all.t) << "ray " << r;
  }
}

TEST(Bvh, EverySphereIsInOneLeafAndEveryBoxHoldsItsSpheres) {
  const Scene scene = randomSpheres(2000, 40.0, 1);
  const SphereBvh bvh = buildSphereBvh(scene.spheres);
  std::vector<uint32_t> below = spheresBelow(bvh, scene, 0);
  ASSERT_EQ(below.size(), scene.spheres.size());
  std::sort(below.begin(), below.end());
  for (uint32_t i = 0; i < below.size(); ++i) EXPECT_EQ(below[i], i);
  for (const BvhNode& n : bvh.nodes) EXPECT_LE(n.count, kBvhLeafSize);
  // A tree, not a list: about 2N / leaf size nodes.
  EXPECT_LT(bvh.nodes.size(), 2 * scene.spheres.size());
}

TEST(Bvh, ClosestHitsMatchTestingEverySphere) {
  expectSameHits(randomSpheres(3000, 30.0, 2), 30.0, 3);
  expectSameHits(randomSpheres(7, 5.0, 4), 5.0, 5);
  expectSameHits(randomSpheres(1, 5.0, 6), 5.0, 7);
}

TEST(Bvh, SpheresAtOnePointAndNoSpheres) {
  Scene same;
  for (int i = 0; i < 50; ++i) {
    Sphere s;
    s.center = {1.0, 2.0, 3.0};
    s.radius = 0.1 + 0.01 * i;
    same.spheres.push_back(s);
  }
  const SphereBvh bvh = buildSphereBvh(same.spheres);
  EXPECT_EQ(spheresBelow(bvh, same, 0).size(), 50u);
  expectSameHits(same, 4.0, 8);
  const SphereBvh empty = buildSphereBvh({});
  EXPECT_TRUE(empty.nodes.empty());
  EXPECT_EQ(referenceClosestHit(Scene{}, glm::dvec3(0.0), glm::dvec3(0, 0, -1), false, &empty).kind, 0);
}

}  // namespace

// The tree as the kernel walks it (gpu_tree.h), laid out for a camera at the origin.
namespace {

std::vector<gpu::Sphere> packedAroundOrigin(const Scene& scene) {
  std::vector<gpu::Sphere> packed;
  for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
    gpu::Sphere s{};
    s.centerRadius = glm::vec4(glm::vec3(scene.spheres[i].center), float(scene.spheres[i].radius));
    s.material = i;  // which sphere it is, to follow the reordering
    packed.push_back(s);
  }
  return packed;
}

// Checks node `node`'s subtree: boxes hold their spheres' float boxes and their children's,
// `next` is the node after the subtree, the nearer child first; returns the spheres' ids.
std::vector<uint32_t> checkLaidOut(const std::vector<gpu::BvhNode>& nodes, const std::vector<gpu::Sphere>& spheres,
                                   uint32_t node) {
  const gpu::BvhNode& n = nodes[node];
  std::vector<uint32_t> ids;
  const uint32_t count = n.spheres >> TREE_LEAF_SHIFT;
  if (count > 0) {
    EXPECT_LE(count, TREE_LEAF_SIZE);
    EXPECT_EQ(n.next, node + 1);
    for (uint32_t k = 0; k < count; ++k) {
      const gpu::Sphere& s = spheres[(n.spheres & ((1u << TREE_LEAF_SHIFT) - 1)) + k];
      for (int a = 0; a < 3; ++a) {
        EXPECT_LT(n.lo[a], s.centerRadius[a] - s.centerRadius.w);
        EXPECT_GT(n.hi[a], s.centerRadius[a] + s.centerRadius.w);
      }
      ids.push_back(s.material);
    }
    return ids;
  }
  const uint32_t first = node + 1, second = nodes[first].next;
  EXPECT_LT(second, n.next);
  for (uint32_t child : {first, second})
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(n.lo[a], nodes[child].lo[a]);
      EXPECT_GE(n.hi[a], nodes[child].hi[a]);
    }
  auto distance = [&](uint32_t c) { return glm::length(glm::dvec3(nodes[c].lo) + glm::dvec3(nodes[c].hi)); };
  EXPECT_LE(distance(first), distance(second));
  ids = checkLaidOut(nodes, spheres, first);
  std::vector<uint32_t> more = checkLaidOut(nodes, spheres, second);
  EXPECT_EQ(nodes[second].next, n.next);
  ids.insert(ids.end(), more.begin(), more.end());
  return ids;
}

}  // namespace

TEST(GpuTree, LayoutHoldsEverySphereOnceNearerChildFirstWithSkipLinks) {
  const Scene scene = randomSpheres(3000, 30.0, 8);
  const SphereBvh bvh = buildSphereBvh(scene.spheres);
  std::vector<gpu::Sphere> spheres = packedAroundOrigin(scene);
  std::vector<gpu::BvhNode> nodes;
  layoutSphereTree(bvh, spheres, nodes);
  ASSERT_EQ(nodes.size(), bvh.nodes.size());
  ASSERT_EQ(spheres.size(), scene.spheres.size());
  EXPECT_EQ(nodes[0].next, nodes.size());
  std::vector<uint32_t> ids = checkLaidOut(nodes, spheres, 0);
  std::sort(ids.begin(), ids.end());
  ASSERT_EQ(ids.size(), scene.spheres.size());
  for (uint32_t i = 0; i < ids.size(); ++i) EXPECT_EQ(ids[i], i);
}

TEST(GpuTree, FewSpheresKeepTheLoopAndManyGoToStorage) {
  EXPECT_EQ(sphereTreeFor(SPHERE_TREE_MIN_SPHERES - 1), uint32_t(SPHERE_TREE_NONE));
  EXPECT_EQ(sphereTreeFor(SPHERE_TREE_MIN_SPHERES), uint32_t(SPHERE_TREE_UNIFORM));
  EXPECT_EQ(sphereTreeFor(MAX_UNIFORM_SPHERES), uint32_t(SPHERE_TREE_UNIFORM));
  EXPECT_EQ(sphereTreeFor(MAX_UNIFORM_SPHERES + 1), uint32_t(SPHERE_TREE_STORAGE));
}

// The per-tile lists (tile_lists.h) are conservative: every sphere a pixel's ray hits is listed
// for its tile, and a sphere that reaches the camera plane is in every tile. Each list runs
// nearest first.
TEST(TileLists, EveryHitSphereIsListedForItsPixelsTile) {
  Scene scene = randomSpheres(400, 30.0, 9);
  scene.camera.eye = {0.0, 0.0, 40.0};
  scene.camera.lookat = {0.0, 0.0, 0.0};
  scene.spheres[5].center = {0.3, 0.2, 40.2};  // around the eye: every tile
  const uint32_t w = 200, h = 120;
  gpu::Frame f = cameraFrame(scene.camera, w, h);
  std::vector<gpu::Sphere> packed;
  for (const Sphere& s : scene.spheres)
    packed.push_back({glm::vec4(glm::vec3(s.center - scene.camera.eye), float(s.radius))});
  const TileLists lists = buildTileLists(f, packed);
  ASSERT_EQ(lists.columns, 25u);
  ASSERT_EQ(lists.rows, 15u);
  auto listed = [&](uint32_t tile, uint32_t sphere) {
    const uint32_t first = lists.ranges[2 * tile], count = lists.ranges[2 * tile + 1];
    if (count == TILE_USE_TREE) return true;
    return std::find(lists.spheres.begin() + first, lists.spheres.begin() + first + count, sphere) !=
           lists.spheres.begin() + first + count;
  };
  auto nearest = [&](uint32_t i) { return glm::length(glm::dvec3(packed[i].centerRadius)) - packed[i].centerRadius.w; };
  int hits = 0, walks = 0;
  for (uint32_t t = 0; t < lists.columns * lists.rows; ++t) {
    const uint32_t first = lists.ranges[2 * t], count = lists.ranges[2 * t + 1];
    walks += count == TILE_USE_TREE;
    EXPECT_TRUE(listed(t, 5)) << "tile " << t;
    for (uint32_t k = 1; count != TILE_USE_TREE && k < count; ++k)  // nearest first
      EXPECT_LE(nearest(lists.spheres[first + k - 1]), nearest(lists.spheres[first + k])) << "tile " << t;
  }
  scene.spheres.erase(scene.spheres.begin() + 5);  // the rays from inside it hit it first
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye,
                                                   referenceRayDirection(scene.camera, int(w), int(h), int(x), int(y)), false);
      if (hit.kind != 2) continue;
      ++hits;
      const uint32_t sphere = hit.index >= 5 ? hit.index + 1 : hit.index;  // its index before the erase
      EXPECT_TRUE(listed((y / TILE_SIZE) * lists.columns + x / TILE_SIZE, sphere)) << x << ", " << y;
    }
  EXPECT_GT(hits, int(w * h / 20));
  EXPECT_LT(walks, int(lists.columns * lists.rows / 4));  // most tiles have lists
}
