// What a trace kernel is built for: every specialisation constant (SPEC_* in shaders/common.h)
// by name, in one key made by one function from a packed scene and the render's options. The
// pipeline cache (frame_kernels.cpp) is keyed on it and createTracePipeline (pipeline.cpp) maps its
// fields to the constants. No Vulkan.
#pragma once

#include "common.h"
#include "scene.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

struct GpuScene;

// What a trace kernel is specialised to in a scene (the scene's SPEC_* constants of common.h).
// The defaults are the unspecialised kernel: every kind, counts read from Frame.
struct SceneShape {
  uint32_t sphereKinds = ~0u;  // bit (1 << TEX_*) per kind on a sphere
  uint32_t planeKinds = ~0u;   // ... on a plane
  uint32_t sphereCount = COUNT_FROM_FRAME;  // the count if at most MAX_SPECIALISED_COUNT
  uint32_t planeCount = COUNT_FROM_FRAME;
  uint32_t lightCount = COUNT_FROM_FRAME;
  uint32_t placed = 1;  // SPEC_TEXTURE_PLACEMENT (a VkBool32): an object's placement needs the kernel's
  uint32_t imageCount = MAX_IMAGES;  // image files the objects use (SPEC_IMAGE_COUNT)
  uint32_t sphereTree = SPHERE_TREE_NONE;  // SPEC_SPHERE_TREE: how the spheres are walked
  uint32_t tileLists = 0;  // SPEC_TILE_LISTS (a VkBool32): primary rays test their tile's spheres
  uint32_t shadowLists = 0;  // SPEC_SHADOW_LISTS (a VkBool32): shadow rays test their cell's and light's
  uint32_t kinds() const { return sphereKinds | planeKinds; }
  bool operator==(const SceneShape& o) const { return std::memcmp(this, &o, sizeof(SceneShape)) == 0; }
};

// A scene's spheres, planes, lights and materials as the words of SPEC_BAKED_WORDS (laid out as
// the uniform blocks' structs, common.h), for a kernel with their values built in.
struct BakedScene {
  uint32_t enabled = 0;        // SPEC_BAKED (a VkBool32)
  uint32_t materialCount = 1;  // SPEC_BAKED_MATERIAL_COUNT
  std::array<uint32_t, BAKED_WORD_COUNT> words{};
  bool operator==(const BakedScene& o) const { return std::memcmp(this, &o, sizeof(BakedScene)) == 0; }
};

// The render's side of the key.
struct KernelOptions {
  uint32_t outputMode = OUTPUT_SHADED;  // OUTPUT_*: the debug outputs use their own build variant
  uint32_t textureFilter = FILTER_POINT;  // FILTER_*
  uint32_t imageFilter = IMAGE_FILTER_ANISOTROPIC;  // IMAGE_FILTER_*, with FILTER_BOX or FILTER_COVERAGE
  uint32_t samplesPerSide = 1;          // N x N samples per pixel
  bool progressive = false;             // one sample per dispatch, accumulated (the viewer)
  bool bakeValues = false;              // the scene's values built in, where they fit (a fixed camera)
};

struct KernelKey {
  SceneShape shape;              // kinds per shape (absent ones compiled out), counts, images
  uint32_t outputMode = OUTPUT_SHADED;  // SPEC_OUTPUT_MODE
  uint32_t textureFilter = FILTER_POINT;  // FILTER_*: selects the kernel's build variant
  uint32_t imageFilter = IMAGE_FILTER_ANISOTROPIC;  // SPEC_IMAGE_FILTER
  uint32_t samplesPerSide = 1;   // SPEC_SAMPLES_PER_SIDE
  uint32_t progressive = 0;      // SPEC_PROGRESSIVE (a VkBool32)
  BakedScene baked;              // SPEC_BAKED and the words, when options.bakeValues
  uint32_t loopBudget = 0;       // SPEC_LOOP_BUDGET: set by the renderer for its device
  uint32_t tileOrder = 0;        // SPEC_TILE_ORDER (a VkBool32): one of a frame's tile kernels
  // SPEC_PASS_MASK: bit (1 << AOV_*) per pass; nonzero selects the pass variant (RAYTEX_AOV) of
  // the shaded output. Set by the renderer from Renderer::passMask, the passes its buffer holds.
  uint32_t passMask = 0;
  // FILTER_COVERAGE's edge pass (the RAYTEX_EDGE_PASS variant, an indirect dispatch over the
  // listed edge pixels) rather than its main kernel; set by the renderer (edgePassKey).
  uint32_t edgePass = 0;
  // Two keys (and shapes, and baked scenes) are equal when all their words are: they are words
  // only, with no padding.
  bool operator==(const KernelKey& o) const { return std::memcmp(this, &o, sizeof(KernelKey)) == 0; }
};
static_assert(std::has_unique_object_representations_v<KernelKey>, "a KernelKey is words only, with no padding");

// A specialisation constant of the trace kernel: where its value lies in KernelKey. The pipeline's
// map entries (pipeline.cpp) are made from these rows, one per SPEC_* of shaders/common.h; the
// kernel declares each with its constant_id.
struct SpecConstant {
  uint32_t id;      // SPEC_*: the first of `words` consecutive ids
  uint32_t offset;  // its first word's byte offset in KernelKey
  uint32_t words;   // 1, or BAKED_WORD_COUNT for SPEC_BAKED_WORDS
  bool (*declared)(const KernelKey& key);  // whether the key's kernel declares it; nullptr: every kernel
};

// Every constant, in SPEC_* order. The words of KernelKey that are no constant: edgePass (it picks
// the build variant only).
const std::vector<SpecConstant>& specConstants();

// The kernel's FILTER_* for a render's filter, and its IMAGE_FILTER_* for an image filter.
uint32_t kernelFilter(TextureFilter filter);
uint32_t kernelImageFilter(ImageFilter filter);

// The key of the kernel that renders `scene` with `options`.
KernelKey kernelKey(const GpuScene& scene, const KernelOptions& options);

// The scene's kinds per shape (kinds(): all in use) and its counts (those over
// MAX_SPECIALISED_COUNT: COUNT_FROM_FRAME); the image files its objects use (at most
// MAX_IMAGES: buildGpuScene refuses more); whether any object's placement needs the kernel;
// whether its spheres are walked through a tree (sphereTreeFor).
SceneShape sceneShape(const Scene& scene);

// The scene's values for a kernel built around them; not enabled if it has more than
// MAX_BAKED_* spheres, planes, lights or materials (or none of a kind of object: the kernel
// then keeps its one empty slot) or counts that are not specialised.
BakedScene bakeScene(const GpuScene& gpuScene);
