#include "kernel_key.h"

#include "gpu_scene.h"
#include "gpu_tree.h"
#include "shadow_lists.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

namespace {

bool withPasses(const KernelKey& key) { return key.passMask != 0; }
bool withBakedValues(const KernelKey& key) { return key.baked.enabled != 0; }

std::vector<SpecConstant> makeSpecConstants() {
#define RAYTEX_AT(field) uint32_t(offsetof(KernelKey, field))
  return {
      {SPEC_SPHERE_TEXTURE_KINDS, RAYTEX_AT(shape.sphereKinds), 1, nullptr},
      {SPEC_OUTPUT_MODE, RAYTEX_AT(outputMode), 1, nullptr},
      {SPEC_SAMPLES_PER_SIDE, RAYTEX_AT(samplesPerSide), 1, nullptr},
      {SPEC_PROGRESSIVE, RAYTEX_AT(progressive), 1, nullptr},
      {SPEC_PLANE_TEXTURE_KINDS, RAYTEX_AT(shape.planeKinds), 1, nullptr},
      {SPEC_SPHERE_COUNT, RAYTEX_AT(shape.sphereCount), 1, nullptr},
      {SPEC_PLANE_COUNT, RAYTEX_AT(shape.planeCount), 1, nullptr},
      {SPEC_LIGHT_COUNT, RAYTEX_AT(shape.lightCount), 1, nullptr},
      {SPEC_BAKED, RAYTEX_AT(baked.enabled), 1, nullptr},
      {SPEC_BAKED_MATERIAL_COUNT, RAYTEX_AT(baked.materialCount), 1, nullptr},
      {SPEC_TEXTURE_PLACEMENT, RAYTEX_AT(shape.placed), 1, nullptr},
      {SPEC_IMAGE_COUNT, RAYTEX_AT(shape.imageCount), 1, nullptr},
      {SPEC_SPHERE_TREE, RAYTEX_AT(shape.sphereTree), 1, nullptr},
      {SPEC_LOOP_BUDGET, RAYTEX_AT(loopBudget), 1, nullptr},
      {SPEC_TILE_LISTS, RAYTEX_AT(shape.tileLists), 1, nullptr},
      {SPEC_TILE_ORDER, RAYTEX_AT(tileOrder), 1, nullptr},
      {SPEC_SHADOW_LISTS, RAYTEX_AT(shape.shadowLists), 1, nullptr},
      // Only the pass variant declares the pass mask: without passes the constants are as before it.
      {SPEC_PASS_MASK, RAYTEX_AT(passMask), 1, withPasses},
      {SPEC_TEXTURE_FILTER, RAYTEX_AT(textureFilter), 1, nullptr},
      {SPEC_IMAGE_FILTER, RAYTEX_AT(imageFilter), 1, nullptr},
      {SPEC_BAKED_WORDS, RAYTEX_AT(baked.words), BAKED_WORD_COUNT, withBakedValues},
  };
#undef RAYTEX_AT
}

}  // namespace

const std::vector<SpecConstant>& specConstants() {
  static const std::vector<SpecConstant> constants = makeSpecConstants();
  return constants;
}

uint32_t kernelFilter(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Point: return FILTER_POINT;
    case TextureFilter::Box: return FILTER_BOX;
    case TextureFilter::Coverage: return FILTER_COVERAGE;
  }
  return FILTER_POINT;
}

static_assert(2 * EWA_MAX_TEXELS + 1 <= 33, "EWA's two levels fit the loop passes reserved for the image filter");

uint32_t kernelImageFilter(ImageFilter filter) {
  switch (filter) {
    case ImageFilter::Anisotropic: return IMAGE_FILTER_ANISOTROPIC;
    case ImageFilter::Trilinear: return IMAGE_FILTER_TRILINEAR;
    case ImageFilter::Bilinear: return IMAGE_FILTER_BILINEAR;
    case ImageFilter::Ewa: return IMAGE_FILTER_EWA;
    case ImageFilter::Stochastic: return IMAGE_FILTER_STOCHASTIC;
  }
  return IMAGE_FILTER_ANISOTROPIC;
}

KernelKey kernelKey(const GpuScene& scene, const KernelOptions& options) {
  KernelKey key;
  key.shape = scene.shape;
  key.outputMode = options.outputMode;
  key.textureFilter = options.textureFilter;
  key.imageFilter = options.textureFilter == FILTER_POINT ? IMAGE_FILTER_ANISOTROPIC : options.imageFilter;
  key.samplesPerSide = options.samplesPerSide;
  key.progressive = options.progressive ? 1u : 0u;
  if (options.bakeValues) key.baked = bakeScene(scene);
  return key;
}

SceneShape sceneShape(const Scene& scene) {
  Material fallback = defaultMaterial();
  auto kindBit = [&](int m) { return 1u << uint32_t(materialAt(scene, m, fallback).texture.kind); };
  auto count = [](size_t n) { return n <= MAX_SPECIALISED_COUNT ? uint32_t(n) : COUNT_FROM_FRAME; };
  std::vector<std::string> images;  // distinct image files, as probeSceneImages counts them
  auto noteImage = [&](int m) {
    const TextureDesc& t = materialAt(scene, m, fallback).texture;
    if (t.kind == TextureKind::Image && std::find(images.begin(), images.end(), t.imagePath) == images.end())
      images.push_back(t.imagePath);
  };
  SceneShape shape;
  shape.sphereKinds = shape.planeKinds = 0;
  for (const Sphere& s : scene.spheres) {
    shape.sphereKinds |= kindBit(s.material);
    noteImage(s.material);
  }
  for (const Plane& p : scene.planes) {
    shape.planeKinds |= kindBit(p.material);
    noteImage(p.material);
  }
  shape.imageCount = uint32_t(std::min<size_t>(images.size(), MAX_IMAGES));
  shape.sphereCount = count(scene.spheres.size());
  shape.planeCount = count(scene.planes.size());
  shape.lightCount = count(scene.lights.size());
  shape.sphereTree = sphereTreeFor(scene.spheres.size());
  shape.tileLists = shape.sphereTree != SPHERE_TREE_NONE;
  shape.shadowLists = shape.tileLists && shadowListsFit(scene.lights.size(), scene.planes.size());
  // A plane's tex_scale and tex_offset, and its turn of (u, v) and the image, are folded into
  // what it packs anyway; its turned solid coordinate and a sphere's placement are not.
  const TexturePlacement none;
  shape.placed = 0;
  for (const Sphere& s : scene.spheres)
    shape.placed |= s.placement.rotate != none.rotate || s.placement.scale != none.scale ||
                    s.placement.offset != none.offset;
  for (const Plane& p : scene.planes) shape.placed |= p.placement.rotate != none.rotate;
  return shape;
}

BakedScene bakeScene(const GpuScene& g) {
  BakedScene baked;
  const SceneShape& shape = g.shape;
  if (shape.sphereCount == COUNT_FROM_FRAME || shape.planeCount == COUNT_FROM_FRAME ||
      shape.lightCount == COUNT_FROM_FRAME || g.spheres.size() > MAX_BAKED_SPHERES ||
      g.planes.size() > MAX_BAKED_PLANES || g.lights.size() > MAX_BAKED_LIGHTS || g.materials.empty() ||
      g.materials.size() > MAX_BAKED_MATERIALS)
    return baked;
  auto put = [&](uint32_t word, uint32_t stride, const auto& items) {
    for (size_t k = 0; k < items.size(); ++k)
      std::memcpy(baked.words.data() + word + k * stride, &items[k], sizeof(items[k]));
  };
  put(BAKED_SPHERE_WORD, BAKED_SPHERE_STRIDE, g.spheres);
  put(BAKED_PLANE_WORD, BAKED_PLANE_STRIDE, g.planes);
  put(BAKED_LIGHT_WORD, BAKED_LIGHT_STRIDE, g.lights);
  put(BAKED_MATERIAL_WORD, BAKED_MATERIAL_STRIDE, g.materials);
  baked.enabled = 1;
  baked.materialCount = uint32_t(g.materials.size());
  return baked;
}
