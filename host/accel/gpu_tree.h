// The sphere tree as the kernel walks it (shaders/sphere_tree.glsl): the host's tree
// (bvh.h) laid out for one camera, with boxes around the camera-relative spheres the kernel
// tests. No Vulkan.
#pragma once

#include "bvh.h"
#include "common.h"
#include "scene_limits.h"  // sphereTreeFor

#include <cstdint>
#include <vector>

// A laid-out node's spheres (BvhNode.spheres): its count (0 for an inner node) and its first.
inline uint32_t treeLeafCount(const gpu::BvhNode& n) { return n.spheres >> TREE_LEAF_SHIFT; }
inline uint32_t treeLeafFirst(const gpu::BvhNode& n) { return n.spheres & ((1u << TREE_LEAF_SHIFT) - 1u); }

// `tree` laid out over `spheres` (packed for the camera at the origin, in the scene's order):
// writes the nodes and puts the spheres in leaf order, which the nodes index. Each box is
// built from the floats the kernel reads and rounded outward, padded for the kernel's float
// rounding; each inner node's child nearer the camera comes first, so that a primary ray finds
// its nearest hit early and skips the boxes behind it.
void layoutSphereTree(const SphereBvh& tree, std::vector<gpu::Sphere>& spheres, std::vector<gpu::BvhNode>& nodes);
