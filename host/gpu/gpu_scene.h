// Packs a parsed Scene into the structs of shaders/common.h: only what the
// scene's objects use goes to the GPU. No Vulkan.
#pragma once

#include "bvh.h"
#include "common.h"
#include "mip_chain.h"
#include "kernel_key.h"
#include "scene.h"
#include "scene_images.h"
#include "tile_lists.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

// One image file's texels as uploaded: RGBA8 sRGB, level 0 (width x height) first, then its
// levels 1.. of the full mip chain when it has them (mipChain in mip_chain.h: level l is
// max(1, width >> l) x max(1, height >> l)), level after level.
struct ImageChain {
  int width = 1, height = 1, levels = 1;
  std::vector<uint8_t> pixels;
};

struct GpuScene {
  gpu::Frame frame{};
  std::vector<gpu::Sphere> spheres;  // in the scene's order, or the tree's leaf order with a tree
  std::vector<gpu::Plane> planes;
  std::vector<gpu::Material> materials;  // those referenced by objects (or all: allMaterials)
  std::vector<gpu::Light> lights;
  // Where shape.sphereTree walks a tree: the tree over the scene's spheres (built once, in world
  // space) and its nodes as laid out for the camera (packCamera).
  SphereBvh sphereTree;
  std::vector<gpu::BvhNode> treeNodes;
  TileLists tiles;  // per-tile sphere lists for the camera and size (none without spheres)
  gpu::NoiseTable noise{};
  SceneShape shape;  // the kinds in use and the counts: what the kernel is specialised to
  std::map<int, uint32_t> materialIndex;  // Scene material (-1: the default) -> index in materials
  // Image files in use, each at its own size: element i of BINDING_IMAGES is file images[i],
  // its texels imageChains[i].
  std::vector<SceneImage> images;
  std::vector<ImageChain> imageChains;
};

// How buildGpuScene packs a scene.
struct PackOptions {
  // The images' mip chains (only the box-filtered kernel reads them; their cost:
  // docs/textures.md, "Filtering image textures").
  bool mipmaps = true;
  // Every material the scene defines, not only those its objects use, so that objects can
  // switch material with packCamera alone (the viewer); shape still holds only the kinds in use.
  bool allMaterials = false;
  // The budget of image bytes uploaded (--max-image-mib; scene_images.h).
  uint32_t maxImageMiB = kDefaultMaxImageMiB;
};

// Throws ImageInputError (at the texture's file location) if an image cannot be loaded, and
// SceneError if the
// images' headers show that they are more than MAX_IMAGES or would upload more than
// options.maxImageMiB: checked before any image is decoded, each then decoded straight into its
// chain. width, height: output size in pixels.
GpuScene buildGpuScene(const Scene& scene, uint32_t width, uint32_t height, const PackOptions& options = {});

// Re-packs what depends on the camera and the output size (the frame, and spheres, planes
// and lights, which are camera-relative) for a scene whose materials are unchanged: cheap,
// unlike buildGpuScene, which also decodes images.
void packCamera(GpuScene& gpuScene, const Scene& scene, uint32_t width, uint32_t height);

// The camera as the kernel sees it: eye at the origin (camera-relative), axes scaled by the
// field of view and aspect. Used by packCamera; exposed for its tests.
gpu::Frame cameraFrame(const Camera& camera, uint32_t width, uint32_t height);
