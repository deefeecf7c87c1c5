#include "reference_render.h"

#include "common.h"
#include "parallel.h"
#include "reference.h"
#include "texture.h"
#include "texture_kinds.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace {

struct Context {
  const Scene& scene;
  const std::map<std::string, ImageRGBA8>& images;
  Material fallback;
  SphereBvh bvh;  // over scene.spheres: primary and shadow rays test the spheres along them
};

const Material& materialOf(const Context& c, const ReferenceHit& hit) {
  int index = hit.kind == 1 ? c.scene.planes[size_t(hit.index)].material
                            : c.scene.spheres[size_t(hit.index)].material;
  return materialAt(c.scene, index, c.fallback);
}

// Phong with hard shadows (docs/scene-format.md, "Shading").
glm::dvec3 shadeReference(const Context& c, glm::dvec3 o, glm::dvec3 d) {
  const Scene& scene = c.scene;
  ReferenceHit hit = referenceClosestHit(scene, o, d, true, &c.bvh);
  if (hit.kind == 0) return glm::dvec3(scene.background);
  const Material& m = materialOf(c, hit);
  glm::dvec3 n = glm::dot(hit.n, d) > 0.0 ? -hit.n : hit.n;
  glm::dvec3 albedo = referenceAlbedo(c.images, m, hit);
  bool textured = m.texture.kind != TextureKind::None;
  glm::dvec3 color = glm::dvec3(scene.ambientLight) * glm::dvec3(m.ambient) * (textured ? albedo : glm::dvec3(1.0));
  // Double precision leaves ~1e-16 relative error, so a tiny offset clears self-hits.
  double scale = std::max({1.0, std::abs(hit.p.x), std::abs(hit.p.y), std::abs(hit.p.z)});
  glm::dvec3 origin = hit.p + n * (scale * 1e-9);
  for (const Light& light : scene.lights) {
    glm::dvec3 toLight = glm::dvec3(light.position) - hit.p;
    double dist = glm::length(toLight);
    if (!(dist > 0.0)) continue;
    glm::dvec3 l = toLight / dist;
    double nDotL = glm::dot(n, l);
    if (nDotL <= 0.0) continue;
    ReferenceHit blocker = referenceClosestHit(scene, origin, l, false, &c.bvh);
    if (blocker.kind != 0 && blocker.t < dist) continue;
    glm::dvec3 r = 2.0 * nDotL * n - l;
    double rDotV = std::max(glm::dot(r, -d), 0.0);
    glm::dvec3 specular = rDotV > 0.0 ? glm::dvec3(m.specular) * std::pow(rDotV, double(m.shininess)) : glm::dvec3(0.0);
    color += glm::dvec3(light.color) * (albedo * nDotL + specular);
  }
  return glm::min(color, glm::dvec3(RADIANCE_LIMIT));  // as the kernel (double cannot overflow here)
}

}  // namespace

glm::dvec3 referenceAlbedo(const std::map<std::string, ImageRGBA8>& images, const Material& m, const ReferenceHit& hit) {
  switch (m.texture.kind) {
    case TextureKind::None:
      return glm::dvec3(m.diffuse);
    case TextureKind::Image:
      return sampleImageReference(images.at(m.texture.imagePath), hit.tc, m.texture.wrap);
    default:
      return textureColorReference(m.texture, hit.tc);
  }
}

std::map<std::string, ImageRGBA8> loadReferenceImages(const Scene& scene, uint32_t maxImageMiB) {
  std::vector<int> used;
  for (const Sphere& s : scene.spheres) used.push_back(s.material);
  for (const Plane& p : scene.planes) used.push_back(p.material);
  std::map<std::string, ImageRGBA8> images;
  for (const SceneImage& probed : probeSceneImages(scene, used, false, maxImageMiB)) {
    ImageRGBA8& image = images[probed.path];
    image.pixels.resize(size_t(probed.header.width) * probed.header.height * 4);
    decodeSceneImage(probed, image.pixels.data());
    image.width = probed.header.width;
    image.height = probed.header.height;
  }
  return images;
}

glm::dvec3 sampleImageReference(const ImageRGBA8& image, const TexCoordD& tc, ImageWrap wrap) {
  const int w = image.width, h = image.height;
  const bool clampU = wrap == ImageWrap::Clamp;
  const bool clampV = tc.clampV || clampU;
  const glm::dvec2 st = clampU ? glm::clamp(tc.imageTile + tc.image, 0.0, 1.0) : tc.image;
  double x = st.x * w;
  double y = st.y * h;
  if (clampU) x = std::clamp(x, 0.5, w - 0.5);
  if (clampV) y = std::clamp(y, 0.5, h - 0.5);
  x -= 0.5;
  y -= 0.5;
  double x0 = std::floor(x), y0 = std::floor(y);
  double fx = x - x0, fy = y - y0;
  auto texel = [&](double xi, double yi) {
    int ix = clampU ? int(std::clamp(xi, 0.0, double(w - 1))) : int(xi - w * std::floor(xi / w));
    int iy = clampV ? int(std::clamp(yi, 0.0, double(h - 1))) : int(yi - h * std::floor(yi / h));
    const uint8_t* p = &image.pixels[(size_t(iy) * w + ix) * 4];
    return glm::dvec3(srgbToLinear(p[0] / 255.0), srgbToLinear(p[1] / 255.0), srgbToLinear(p[2] / 255.0));
  };
  return (texel(x0, y0) * (1 - fx) + texel(x0 + 1, y0) * fx) * (1 - fy) +
         (texel(x0, y0 + 1) * (1 - fx) + texel(x0 + 1, y0 + 1) * fx) * fy;
}

ReferenceImage renderReference(const Scene& scene, int width, int height, int samplesPerSide, int threads,
                               uint32_t maxImageMiB) {
  std::map<std::string, ImageRGBA8> images = loadReferenceImages(scene, maxImageMiB);
  Context context{scene, images, defaultMaterial(), buildSphereBvh(scene.spheres)};
  ReferenceImage out;
  out.width = width;
  out.height = height;
  out.rgb.assign(size_t(width) * height * 3, 0.0);
  const int n = std::max(samplesPerSide, 1);
  const glm::dvec3 eye(scene.camera.eye);
  const ReferenceCamera camera = referenceCamera(scene.camera, width, height);
  forEachRowInParallel(height, threads, [&](int y) {
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0.0);
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx)
          sum += shadeReference(context, eye,
                                referenceRayDirection(camera, x, y, referenceSampleOffset(sx, n),
                                                      referenceSampleOffset(sy, n)));
      sum /= double(n * n);
      double* px = &out.rgb[(size_t(y) * width + x) * 3];
      for (int c = 0; c < 3; ++c) px[c] = sum[c];
    }
  });
  for (double v : out.rgb) out.nonFinite += !std::isfinite(v);
  return out;
}

std::vector<float> referenceToRgba(const ReferenceImage& image) {
  std::vector<float> rgba(size_t(image.width) * image.height * 4, 1.0f);
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
    for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = float(image.rgb[i * 3 + c]);
  return rgba;
}
