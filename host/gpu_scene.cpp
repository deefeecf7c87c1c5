#include "gpu_scene.h"

#include "mapping.h"
#include "noise.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <map>

static_assert(int(TextureKind::None) == TEX_NONE && int(TextureKind::Image) == TEX_IMAGE &&
                  int(TextureKind::Checker) == TEX_CHECKER &&
                  int(TextureKind::SolidChecker) == TEX_SOLID_CHECKER &&
                  int(TextureKind::Noise) == TEX_NOISE && int(TextureKind::Marble) == TEX_MARBLE &&
                  int(TextureKind::Wood) == TEX_WOOD &&
                  int(TextureKind::Turbulence) == TEX_TURBULENCE &&
                  int(TextureKind::DTurbulence) == TEX_DTURBULENCE,
              "TextureKind must match TEX_* in common.h");

namespace {

glm::vec4 v4(const glm::vec3& v, float w = 0.0f) { return glm::vec4(v, w); }

// Materials referenced by objects, in first-use order; -1 stands for the default material.
std::vector<int> usedMaterials(const Scene& scene) {
  std::vector<int> used;
  auto note = [&](int m) {
    if (std::find(used.begin(), used.end(), m) == used.end()) used.push_back(m);
  };
  for (const Sphere& s : scene.spheres) note(s.material);
  for (const Plane& p : scene.planes) note(p.material);
  return used;
}

const Material& materialAt(const Scene& scene, int index, const Material& fallback) {
  return index < 0 ? fallback : scene.materials[size_t(index)];
}

// An image texture's Material.imageIndex and imageSize (common.h): its element of
// BINDING_IMAGES, mip levels, wrap and size.
void packImageFields(gpu::Material& g, const TextureDesc& t, const std::vector<SceneImage>& images, bool mipmaps) {
  uint32_t slot = 0;
  while (images[slot].path != t.imagePath) ++slot;
  const ImageHeader& h = images[slot].header;
  const uint32_t levels = mipmaps ? uint32_t(mipLevelCount(h.width, h.height)) : 1u;
  g.imageIndex = slot | levels << 8 | (t.wrap == ImageWrap::Clamp ? IMAGE_WRAP_CLAMP : 0u);
  g.imageSize = uint32_t(h.width) | uint32_t(h.height) << 16;
}

gpu::Material packMaterial(const Material& m, const std::vector<SceneImage>& images, bool mipmaps) {
  gpu::Material g{};
  g.ambient = v4(m.ambient);
  g.diffuse = v4(m.diffuse);
  g.specular = v4(m.specular, m.shininess);
  g.color1 = v4(m.texture.color1);
  g.color2 = v4(m.texture.color2);
  g.params = glm::vec4(m.texture.scale, m.texture.strength, m.texture.squares, 0.0f);
  g.textureKind = uint32_t(m.texture.kind);
  g.octaves = uint32_t(std::max(m.texture.octaves, 1));
  if (m.texture.kind == TextureKind::Image) packImageFields(g, m.texture, images, mipmaps);
  return g;
}

}  // namespace

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
  return shape;
}

gpu::Frame cameraFrame(const Camera& camera, uint32_t width, uint32_t height) {
  glm::dvec3 forward = glm::normalize(camera.lookat - camera.eye);
  glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  glm::dvec3 up = glm::cross(right, forward);
  double tanHalf = std::tan(glm::radians(camera.fovY) * 0.5);
  double aspect = double(width) / double(height);
  gpu::Frame f{};
  f.eye = glm::vec4(0.0f);  // every GPU position is relative to the camera
  f.cameraRight = v4(glm::vec3(right * tanHalf * aspect));
  f.cameraUp = v4(glm::vec3(up * tanHalf));
  f.cameraForward = v4(glm::vec3(forward));
  f.width = width;
  f.height = height;
  f.bandRows = height;  // one band: the renderer narrows it where the image needs several
  return f;
}

namespace {

// x - P floor(x / P): x reduced into [0, P).
double reduceModulo(double x, double period) { return x - period * std::floor(x / period); }

// The period of a solid texture in solid coordinates, or 0 if it has none.
double solidPeriod(const TextureDesc& t) {
  switch (t.kind) {
    case TextureKind::SolidChecker:
      return 2.0 / double(t.squares);  // parity of floor(solid * squares) summed over axes
    case TextureKind::Noise:
    case TextureKind::Marble:
    case TextureKind::Turbulence:
    case TextureKind::DTurbulence:
      return 256.0 / double(t.scale);  // the noise lattice repeats every 256 (marble's sine every 2)
    default:
      return 0.0;  // wood's rings are not periodic
  }
}

// x clamped to +-TEXCOORD_LIMIT, as the kernel clamps its coordinates.
double clampTexCoord(double x) { return std::clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }

// An image texture with wrap = clamp: the kernel needs the tile index itself, not its parity.
bool imageClamped(const TextureDesc& t) { return t.kind == TextureKind::Image && t.wrap == ImageWrap::Clamp; }

// The camera's tile as a float that is exact, so that the kernel's tile + uv lies in [0, 1]
// in exactly the decal's tile: whole numbers up to 2^24 are exact floats, and a camera farther
// than that many tiles from the decal sees it below a texel of float precision anyway.
glm::dvec2 exactTile(glm::dvec2 cell) { return glm::clamp(cell, glm::dvec2(-16777216.0), glm::dvec2(16777216.0)); }

// The plane's texture frame and the camera's position folded into texture offsets, in double.
gpu::Plane packPlane(const Plane& p, const TextureDesc& texture, glm::dvec3 eye, uint32_t material) {
  // The frame is built once here by the same rule the CPU reference uses.
  PlaneFrame pf = planeFrame(p.normal, p.distance);
  // tex_scale as the kernel divides by it: a normal float (a subnormal may be flushed to 0).
  const double s = std::clamp(p.texScale, double(FLT_MIN), double(FLT_MAX));
  gpu::Plane gp{};
  gp.normalDistance = glm::vec4(glm::vec3(pf.normal), float(pf.distance - glm::dot(pf.normal, eye)));
  gp.tangentScale = glm::vec4(glm::vec3(pf.tangent), float(s));
  gp.binormal = glm::vec4(glm::vec3(pf.binormal), 0.0f);
  glm::dvec2 st(glm::dot(eye, pf.tangent) / s, glm::dot(eye, pf.binormal) / s);
  glm::dvec2 cell = glm::floor(st);
  glm::dvec2 tile = imageClamped(texture) ? exactTile(cell)
                                          : glm::dvec2(reduceModulo(cell.x, 4096.0), reduceModulo(cell.y, 4096.0));
  gp.uvOffset = glm::vec4(float(st.x - cell.x), float(st.y - cell.y), float(tile.x), float(tile.y));
  glm::dvec3 solid = eye / s;
  double period = solidPeriod(texture);
  if (period > 0.0)
    solid = glm::dvec3(reduceModulo(solid.x, period), reduceModulo(solid.y, period), reduceModulo(solid.z, period));
  solid = glm::dvec3(clampTexCoord(solid.x), clampTexCoord(solid.y), clampTexCoord(solid.z));
  gp.solidOffset = glm::vec4(glm::vec3(solid), 0.0f);
  gp.material = material;
  return gp;
}

// Each image at its own size, decoded straight into its chain, its mip levels written after
// level 0 row by row (writeMipLevels).
void fillImageChains(GpuScene& g, bool mipmaps) {
  for (const SceneImage& image : g.images) {
    ImageChain chain{image.header.width, image.header.height, 1, {}};
    chain.levels = mipmaps ? mipLevelCount(chain.width, chain.height) : 1;
    chain.pixels.resize(size_t(imageChainBytes(image.header, mipmaps)));
    decodeSceneImage(image, chain.pixels.data());
    std::vector<uint8_t*> levels;
    uint8_t* next = chain.pixels.data() + size_t(chain.width) * chain.height * 4;
    for (int level = 1; level < chain.levels; ++level) {
      levels.push_back(next);
      next += size_t(std::max(1, chain.width >> level)) * size_t(std::max(1, chain.height >> level)) * 4;
    }
    if (chain.levels > 1) writeMipLevels(chain.pixels.data(), chain.width, chain.height, levels.data());
    g.imageChains.push_back(std::move(chain));
  }
}

// The scene's other materials after the objects' ones in `packed`, up to MAX_MATERIALS, less
// those whose image file would be past the first MAX_IMAGES (packed when an object takes them).
void addOtherMaterials(const Scene& scene, std::vector<int>& packed) {
  std::vector<std::string> images;
  auto imageFits = [&](int m) {
    const TextureDesc& t = scene.materials[size_t(m)].texture;
    if (t.kind != TextureKind::Image || std::find(images.begin(), images.end(), t.imagePath) != images.end())
      return true;
    if (images.size() == MAX_IMAGES) return false;
    images.push_back(t.imagePath);
    return true;
  };
  for (int m : packed)
    if (m >= 0) imageFits(m);
  for (int m = 0; m < int(scene.materials.size()) && packed.size() < MAX_MATERIALS; ++m)
    if (std::find(packed.begin(), packed.end(), m) == packed.end() && imageFits(m)) packed.push_back(m);
}

}  // namespace

void packCamera(GpuScene& g, const Scene& scene, uint32_t width, uint32_t height) {
  gpu::Frame f = cameraFrame(scene.camera, width, height);
  f.background = v4(scene.background);
  f.ambientLight = v4(scene.ambientLight);
  // Camera-relative positions, subtracted in double.
  Material fallback = defaultMaterial();
  const glm::dvec3 eye = scene.camera.eye;
  g.spheres.clear();
  g.planes.clear();
  g.lights.clear();
  for (const Sphere& s : scene.spheres) {
    gpu::Sphere gs{};
    gs.centerRadius = glm::vec4(glm::vec3(s.center - eye), float(s.radius));
    gs.material = g.materialIndex.at(s.material);
    g.spheres.push_back(gs);
  }
  for (const Plane& p : scene.planes)
    g.planes.push_back(packPlane(p, materialAt(scene, p.material, fallback).texture, eye, g.materialIndex.at(p.material)));
  for (const Light& l : scene.lights) g.lights.push_back({v4(glm::vec3(l.position - eye)), v4(l.color)});
  f.sphereCount = uint32_t(g.spheres.size());
  f.planeCount = uint32_t(g.planes.size());
  f.lightCount = uint32_t(g.lights.size());
  g.frame = f;
}

GpuScene buildGpuScene(const Scene& scene, uint32_t width, uint32_t height, const PackOptions& options) {
  GpuScene g;
  // Materials: only the used ones, re-indexed; image files become array layers.
  Material fallback = defaultMaterial();
  std::map<int, uint32_t> materialIndex;
  // The kernel's uniform blocks hold MAX_SPHERES, MAX_PLANES and MAX_LIGHTS: point at the first
  // one over.
  auto checkCount = [](const auto& items, size_t max, const char* what) {
    if (items.size() > max)
      throw SceneError(items[max].loc, "the scene has " + std::to_string(items.size()) + " " + what +
                                           "; raytex renders at most " + std::to_string(max));
  };
  checkCount(scene.spheres, MAX_SPHERES, "spheres");
  checkCount(scene.planes, MAX_PLANES, "planes");
  checkCount(scene.lights, MAX_LIGHTS, "lights");
  // Each light's shadow ray tests every object (kMaxLoopIterations): point at the first light
  // over the limit.
  const size_t objects = scene.spheres.size() + scene.planes.size();
  const uint64_t iterations = loopIterationsPerSample(scene.lights.size(), objects);
  if (iterations > kMaxLoopIterations) {
    // With n lights, (n + 1) (objects + 1) passes the limit from n = limit / (objects + 1) on.
    size_t first = std::min(std::max<size_t>(kMaxLoopIterations / (objects + 1), 1), scene.lights.size()) - 1;
    throw SceneError(scene.lights[first].loc,
                     "the scene has " + std::to_string(scene.lights.size()) + " lights and " +
                         std::to_string(objects) + " objects: (lights + 1) x (objects + 1) = " +
                         std::to_string(iterations) + " intersection tests per sample, raytex does at most " +
                         std::to_string(kMaxLoopIterations));
  }
  std::vector<int> packed = usedMaterials(scene);
  if (packed.size() > MAX_MATERIALS) {  // the kernel's uniform block holds MAX_MATERIALS
    int over = packed[MAX_MATERIALS];
    FileLoc loc = scene.path.empty() ? FileLoc{} : FileLoc{scene.path, 1, 1};
    for (const Sphere& o : scene.spheres)
      if (o.material == over) loc = o.loc;
    for (const Plane& o : scene.planes)
      if (o.material == over) loc = o.loc;
    throw SceneError(loc, "the scene's objects use more than " + std::to_string(MAX_MATERIALS) + " materials");
  }
  if (options.allMaterials) addOtherMaterials(scene, packed);
  g.images = probeSceneImages(scene, packed, options.mipmaps, options.maxImageMiB);
  uint32_t packedKinds = 0;
  for (int m : packed) {
    const Material& material = materialAt(scene, m, fallback);
    materialIndex[m] = uint32_t(g.materials.size());
    g.materials.push_back(packMaterial(material, g.images, options.mipmaps));
    packedKinds |= 1u << uint32_t(material.texture.kind);
  }
  g.shape = sceneShape(scene);

  g.materialIndex = materialIndex;
  packCamera(g, scene, width, height);

  if (packedKinds & ((1u << TEX_NOISE) | (1u << TEX_MARBLE) | (1u << TEX_WOOD) |
                        (1u << TEX_TURBULENCE) | (1u << TEX_DTURBULENCE)))
    fillNoiseTable(&g.noise);

  fillImageChains(g, options.mipmaps);
  return g;
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
