#include "selection.h"

#include "common.h"
#include "texture_kinds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

ReferenceHit hitAt(const Scene& scene, int width, int height, double x, double y) {
  const int px = std::clamp(int(std::floor(x)), 0, width - 1);
  const int py = std::clamp(int(std::floor(y)), 0, height - 1);
  const glm::dvec3 direction =
      referenceRayDirection(scene.camera, width, height, px, py, x - px - 0.5, y - py - 0.5);
  return referenceClosestHit(scene, scene.camera.eye, direction);
}

Selection objectAt(const Scene& scene, int width, int height, double x, double y) {
  const ReferenceHit hit = hitAt(scene, width, height, x, y);
  if (hit.kind == HIT_NONE) return {};
  return {hit.kind, hit.index};
}

std::string selectionName(const Scene& scene, const Selection& s) {
  if (s.kind == HIT_NONE) return "nothing";
  const bool sphere = s.kind == HIT_SPHERE;
  const FileLoc& loc = sphere ? scene.spheres[size_t(s.index)].loc : scene.planes[size_t(s.index)].loc;
  const std::string file = loc.file.substr(loc.file.find_last_of('/') + 1);
  return std::string(sphere ? "sphere " : "plane ") + std::to_string(s.index + 1) + " (" + file + ":" +
         std::to_string(loc.line) + ")";
}

int selectedMaterial(const Scene& scene, const Selection& s) {
  if (s.kind == HIT_SPHERE) return scene.spheres[size_t(s.index)].material;
  if (s.kind == HIT_PLANE) return scene.planes[size_t(s.index)].material;
  return scene.spheres.empty() ? -1 : scene.spheres[0].material;
}

void applyMaterial(Scene& scene, const Selection& s, int index) {
  if (s.kind == HIT_SPHERE) {
    scene.spheres[size_t(s.index)].material = index;
  } else if (s.kind == HIT_PLANE) {
    scene.planes[size_t(s.index)].material = index;
  } else {
    for (Sphere& sphere : scene.spheres) sphere.material = index;
  }
}

int nextMaterial(const Scene& scene, int current, const char* const* course, size_t courseCount) {
  std::vector<int> order;  // the scene's own materials, then the course's, each once
  auto isCourse = [&](const std::string& name) { return std::find(course, course + courseCount, name) != course + courseCount; };
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (!isCourse(scene.materials[i].name)) order.push_back(int(i));
  for (size_t c = 0; c < courseCount; ++c)
    for (size_t i = 0; i < scene.materials.size(); ++i)
      if (scene.materials[i].name == course[c]) order.push_back(int(i));
  if (order.empty()) return -1;
  const auto at = std::find(order.begin(), order.end(), current);
  return at == order.end() || at + 1 == order.end() ? order.front() : *(at + 1);
}

namespace {

std::string formatted(const char* format, double a, double b, double c = 0.0) {
  char text[96];
  snprintf(text, sizeof(text), format, a, b, c);
  return text;
}

// "texel (x, y) of FILE" for the image's lookup at tc, or "" when the image is not packed.
std::string texelReadout(const TextureDesc& texture, const TexCoordD& tc, const std::vector<SceneImage>& images) {
  for (const SceneImage& image : images) {
    if (image.path != texture.imagePath) continue;
    const int w = int(image.header.width), h = int(image.header.height);
    const int x = std::clamp(int(std::floor(tc.image.x * w)), 0, w - 1);
    const int y = std::clamp(int(std::floor(tc.image.y * h)), 0, h - 1);
    return formatted("texel (%.0f, %.0f) of ", x, y) + image.path.substr(image.path.find_last_of('/') + 1);
  }
  return "";
}

}  // namespace

std::string pointReadout(const Scene& scene, const ReferenceHit& hit, const std::vector<SceneImage>& images) {
  if (hit.kind == HIT_NONE) return "background";
  const Selection object{hit.kind, hit.index};
  const Material fallback = defaultMaterial();
  const Material& m = materialAt(scene, selectedMaterial(scene, object), fallback);
  const std::string name = selectionName(scene, object);
  std::string text = name.substr(0, name.find(" (")) + " " + formatted("uv (%.4f, %.4f)", hit.tc.uv.x, hit.tc.uv.y);
  if (m.texture.kind == TextureKind::Image) {
    const std::string texel = texelReadout(m.texture, hit.tc, images);
    if (!texel.empty()) text += " " + texel;
  } else if (isSolidTexture(m.texture.kind)) {
    text += " " + formatted("solid (%.4f, %.4f, %.4f)", hit.tc.solid.x, hit.tc.solid.y, hit.tc.solid.z);
  }
  return text;
}
