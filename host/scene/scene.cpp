#include "scene.h"

#include <algorithm>

Material defaultMaterial() {
  Material m;
  m.name = "default";
  m.ambient = glm::vec3(0.1f);
  m.diffuse = glm::vec3(0.7f);
  m.specular = glm::vec3(0.3f);
  m.shininess = 32.0f;
  return m;
}

const Material& materialAt(const Scene& scene, int index, const Material& fallback) {
  return index < 0 ? fallback : scene.materials[size_t(index)];
}

std::vector<int> usedMaterials(const Scene& scene) {
  std::vector<int> used;
  auto note = [&](int m) {
    if (std::find(used.begin(), used.end(), m) == used.end()) used.push_back(m);
  };
  for (const Sphere& s : scene.spheres) note(s.material);
  for (const Plane& p : scene.planes) note(p.material);
  return used;
}

const char* textureFilterName(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Point: return "point";
    case TextureFilter::Box: return "box";
    case TextureFilter::Coverage: return "coverage";
  }
  return "point";
}

std::optional<TextureFilter> textureFilterNamed(const std::string& name) {
  for (TextureFilter f : {TextureFilter::Point, TextureFilter::Box, TextureFilter::Coverage})
    if (name == textureFilterName(f)) return f;
  return std::nullopt;
}

const char* imageFilterName(ImageFilter filter) {
  switch (filter) {
    case ImageFilter::Anisotropic: return "anisotropic";
    case ImageFilter::Trilinear: return "trilinear";
    case ImageFilter::Bilinear: return "bilinear";
    case ImageFilter::Ewa: return "ewa";
    case ImageFilter::Stochastic: return "stochastic";
  }
  return "anisotropic";
}

std::optional<ImageFilter> imageFilterNamed(const std::string& name) {
  for (ImageFilter f : {ImageFilter::Anisotropic, ImageFilter::Trilinear, ImageFilter::Bilinear, ImageFilter::Ewa,
                        ImageFilter::Stochastic})
    if (name == imageFilterName(f)) return f;
  return std::nullopt;
}
