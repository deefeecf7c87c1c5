#include "gpu_scene.h"

#include "gpu_tree.h"
#include "plane_frame.h"
#include "noise_permutation.h"
#include "scene_limits.h"
#include "shadow_grid.h"
#include "shadow_lists.h"
#include "texture_kinds.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <map>

namespace {

glm::vec4 v4(const glm::vec3& v, float w = 0.0f) { return glm::vec4(v, w); }

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
  packTexture(m.texture, &g);
  if (m.texture.kind == TextureKind::Image) packImageFields(g, m.texture, images, mipmaps);
  return g;
}
}  // namespace


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
  return t.kind == TextureKind::None ? 0.0 : textureKindInfo(t.kind).solidPeriod(t);
}

// x clamped to +-TEXCOORD_LIMIT, as the kernel clamps its coordinates.
double clampTexCoord(double x) { return std::clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }

// An image texture with wrap = clamp: the kernel needs the whole image offset, not its fraction.
bool imageClamped(const TextureDesc& t) { return t.kind == TextureKind::Image && t.wrap == ImageWrap::Clamp; }

// tex_scale as the kernel divides by it: a normal float (a subnormal may be flushed to 0).
double kernelScale(double scale) { return std::clamp(scale, double(FLT_MIN), double(FLT_MAX)); }

// x reduced modulo the solid texture's period (if it has one) and clamped as the kernel clamps.
glm::dvec3 reduceSolid(glm::dvec3 x, const TextureDesc& texture) {
  double period = solidPeriod(texture);
  if (period > 0.0) x = glm::dvec3(reduceModulo(x.x, period), reduceModulo(x.y, period), reduceModulo(x.z, period));
  return glm::dvec3(clampTexCoord(x.x), clampTexCoord(x.y), clampTexCoord(x.z));
}

// tex_rotate's R = Rz Ry Rx (degrees about the fixed axes, x first) as a unit quaternion.
glm::dquat placementQuaternion(glm::dvec3 degrees) {
  auto about = [](double angle, glm::dvec3 axis) { return glm::angleAxis(glm::radians(angle), axis); };
  return about(degrees.z, {0, 0, 1}) * about(degrees.y, {0, 1, 0}) * about(degrees.x, {1, 0, 0});
}

// A quaternion as the kernel reads it (rotateByQuaternion): xyz, w.
glm::vec4 packQuaternion(glm::dquat q) { return glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w)); }

// Where an image's top row points on a plane of unit normal n (docs/textures.md, "Image
// orientation"): world +y in the plane, or -z where the plane is within 45 degrees of level.
glm::dvec3 imageUp(glm::dvec3 n) {
  glm::dvec3 world = n.y * n.y >= 0.5 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
  return glm::normalize(world - glm::dot(world, n) * n);
}

// The sphere's centre relative to the camera and its placement: R^-1 as a quaternion, the scale,
// and tex_offset on the coordinate its kind reads (the solid one reduced modulo its period,
// (u, v) modulo 2, which keeps the checker's tile parity).
gpu::Sphere packSphere(const Sphere& s, const TextureDesc& texture, glm::dvec3 eye, uint32_t material) {
  const TexturePlacement& place = s.placement;
  const bool flat = readsUv(texture.kind);
  gpu::Sphere gs{};
  gs.centerRadius = glm::vec4(glm::vec3(s.center - eye), float(s.radius));
  gs.texRotation = packQuaternion(glm::conjugate(placementQuaternion(place.rotate)));
  glm::dvec3 solid = flat ? glm::dvec3(0.0) : reduceSolid(place.offset, texture);
  gs.solidOffset = glm::vec4(glm::vec3(solid), float(kernelScale(place.scale)));
  gs.material = material;
  gs.uOffset = float(reduceModulo(place.offset.x, 2.0));
  gs.vOffset = float(reduceModulo(place.offset.y, 2.0));
  gs.clampV = place.scale == 1.0 && place.offset.y == 0.0;
  return gs;
}

// The plane's placed texture frame and the camera's position with tex_offset folded into
// texture offsets, in double. The mapping sees n' = R^-1 n: its frame t', b' and image axes for
// n', turned back by R, are the world axes of u, v and the image; o = d n lies on every axis's
// zero (o.R t' = d n'.t' = 0), so only the eye enters the offsets.
gpu::Plane packPlane(const Plane& p, const TextureDesc& texture, glm::dvec3 eye, uint32_t material) {
  const TexturePlacement& place = p.placement;
  // The frame is built once here by the same rule the CPU reference uses.
  PlaneFrame pf = planeFrame(p.normal, p.distance);
  const glm::dmat3 r = glm::mat3_cast(placementQuaternion(place.rotate));
  const glm::dmat3 inverse = glm::transpose(r);
  // (planeFrame renormalises its normal: an unturned frame is kept bit for bit.)
  const bool turns = place.rotate != glm::dvec3(0.0);
  const PlaneFrame turned = turns ? planeFrame(inverse * pf.normal, pf.distance) : pf;
  const glm::dvec3 up = imageUp(turned.normal), right = glm::cross(up, turned.normal);
  const double s = kernelScale(place.scale);
  gpu::Plane gp{};
  gp.normalDistance = glm::vec4(glm::vec3(pf.normal), float(pf.distance - glm::dot(pf.normal, eye)));
  const glm::dvec3 t = r * turned.tangent, b = r * turned.binormal;
  gp.tangentScale = glm::vec4(glm::vec3(t), float(s));
  gp.binormal = glm::vec4(glm::vec3(b), 0.0f);
  glm::dvec2 st(glm::dot(eye, t) / s + place.offset.x, glm::dot(eye, b) / s + place.offset.y);
  glm::dvec2 cell = glm::floor(st);
  gp.uvOffset = glm::vec4(float(st.x - cell.x), float(st.y - cell.y), float(reduceModulo(cell.x, 4096.0)),
                          float(reduceModulo(cell.y, 4096.0)));
  // The image's (column, row): (u, v) with tex_offset, read along right and down in the plane.
  const glm::dvec3 imageX = r * right, imageY = -(r * up);
  const glm::dvec2 offsetUv(place.offset.x, place.offset.y);
  glm::dvec2 image(glm::dot(eye, imageX) / s + offsetUv.x * glm::dot(turned.tangent, right) +
                       offsetUv.y * glm::dot(turned.binormal, right),
                   glm::dot(eye, imageY) / s - offsetUv.x * glm::dot(turned.tangent, up) -
                       offsetUv.y * glm::dot(turned.binormal, up));
  // Repeating images need the offset's fraction alone; a clamped one (a decal) the whole offset,
  // so that the lookup lies in [0, 1] on the decal alone. (Its float rounding grows with the
  // camera's distance in decals, as the decal's size on screen shrinks: a fixed fraction of a
  // pixel.)
  if (!imageClamped(texture)) image = glm::dvec2(reduceModulo(image.x, 1.0), reduceModulo(image.y, 1.0));
  // Image axes only on an image's plane: lavapipe runs an image lookup for every lane of a SIMD
  // group, masked, and with zero axes a lane on another plane reads one texel, not texels spread
  // over the image by that plane's coordinates (docs/performance.md, "Masked image lookups").
  if (texture.kind == TextureKind::Image) {
    gp.imageRight = glm::vec4(glm::vec3(imageX), float(clampTexCoord(image.x)));
    gp.imageDown = glm::vec4(glm::vec3(imageY), float(clampTexCoord(image.y)));
  }
  // solid = (R^-1 (x - o) + o) / s + offset, x = camera-relative + eye: the eye's part here.
  const glm::dvec3 origin = pf.distance * pf.normal;
  gp.solidOffset = glm::vec4(glm::vec3(reduceSolid((inverse * eye + (origin - inverse * origin)) / s + place.offset, texture)), 0.0f);
  gp.texRotation = packQuaternion(glm::conjugate(placementQuaternion(place.rotate)));
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
  for (const Sphere& s : scene.spheres)
    g.spheres.push_back(packSphere(s, materialAt(scene, s.material, fallback).texture, eye, g.materialIndex.at(s.material)));
  for (const Plane& p : scene.planes)
    g.planes.push_back(packPlane(p, materialAt(scene, p.material, fallback).texture, eye, g.materialIndex.at(p.material)));
  for (const Light& l : scene.lights) g.lights.push_back({v4(glm::vec3(l.position - eye)), v4(l.color)});
  if (g.shape.sphereTree != SPHERE_TREE_NONE) layoutSphereTree(g.sphereTree, g.spheres, g.treeNodes);
  // The lists also tell the tile kernels which kinds a tile can show (tile_kernels.h).
  g.tiles = g.spheres.empty() ? TileLists{} : buildTileLists(f, g.spheres);
  if (g.shape.shadowLists) {
    appendShadowLists(f, g.spheres, g.planes, g.lights, g.treeNodes, g.tiles);
    // Only where the kernel reads them (shaders/sphere_tree.glsl, occludedInTile).
    if (g.shape.sphereTree == SPHERE_TREE_STORAGE) appendShadowGrids(g.spheres, g.planes, g.lights, g.tiles);
  }
  f.treeNodeCount = uint32_t(g.treeNodes.size());
  f.tileColumns = g.tiles.columns;
  f.shadowRanges = g.tiles.shadowRanges;
  f.shadowColumns = g.tiles.shadowColumns;
  for (size_t l = 0; l < SHADOW_LIST_MAX_LIGHTS; ++l)
    f.shadowGrids[l] = l < g.tiles.shadowGrids.size() ? g.tiles.shadowGrids[l] : noShadowGrid();
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
  checkSceneLimits(scene);  // also checked when parsed; scenes built in code come here directly
  std::vector<int> packed = usedMaterials(scene);
  if (options.allMaterials) addOtherMaterials(scene, packed);
  g.images = probeSceneImages(scene, packed, options.mipmaps, options.maxImageMiB);
  bool needsNoise = false;
  for (int m : packed) {
    const Material& material = materialAt(scene, m, fallback);
    materialIndex[m] = uint32_t(g.materials.size());
    g.materials.push_back(packMaterial(material, g.images, options.mipmaps));
    if (material.texture.kind != TextureKind::None) needsNoise |= textureKindInfo(material.texture.kind).needsNoise;
  }
  g.shape = sceneShape(scene);
  if (g.shape.sphereTree != SPHERE_TREE_NONE) g.sphereTree = buildSphereBvh(scene.spheres);

  g.materialIndex = materialIndex;
  packCamera(g, scene, width, height);

  if (needsNoise) fillNoiseTable(&g.noise);

  fillImageChains(g, options.mipmaps);
  return g;
}
