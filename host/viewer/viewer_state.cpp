#include "viewer_state.h"

#include "camera_block.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

const char* const kCourseMaterials[kCourseMaterialCount] = {"aSolidChecker", "aNoise",      "aMarble",      "aWood",
                                                            "anImage",       "aTurbulence", "aDturbulence", "aChecker"};

Orbit orbitOf(const Camera& camera) {
  Orbit o;
  o.home = camera;
  o.up = glm::normalize(camera.up);
  glm::dvec3 offset = camera.eye - camera.lookat;
  o.radius = glm::length(offset);
  glm::dvec3 dir = offset / o.radius;
  o.elevation = std::asin(std::clamp(glm::dot(dir, o.up), -1.0, 1.0));
  glm::dvec3 flat = dir - o.up * glm::dot(dir, o.up);
  // The parser rejects an up parallel to the view; fall back to any perpendicular axis.
  o.e1 = glm::length(flat) > 1e-9 ? glm::normalize(flat) : glm::normalize(glm::cross(o.up, glm::dvec3(1, 0, 0)));
  o.e2 = glm::cross(o.up, o.e1);
  return o;
}

int materialIndex(const Scene& scene, const char* name) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return int(i);
  return -1;
}

std::string materialName(const Scene& scene, int index) {
  return index < 0 ? std::string("default") : scene.materials[size_t(index)].name;
}

void moveCamera(ViewerState& state, double dAzimuth, double dElevation, double zoom) {
  Orbit& o = state.orbit;
  o.azimuth += dAzimuth;
  o.elevation = std::clamp(o.elevation + dElevation, -1.55, 1.55);
  o.radius = std::clamp(o.radius * zoom, 1e-3, 1e7);
  glm::dvec3 dir = std::cos(o.elevation) * (std::cos(o.azimuth) * o.e1 + std::sin(o.azimuth) * o.e2) +
                   std::sin(o.elevation) * o.up;
  state.scene.camera.eye = state.scene.camera.lookat + o.radius * dir;
  state.scene.camera = printedCamera(state.scene.camera);  // what C prints is exactly this view
  state.cameraMoved = true;
}

void say(ViewerState& state, std::string message) {
  state.message = std::move(message);
  state.messageAt = Clock::now();
}

TextureFilter nextFilter(TextureFilter filter, TextureFilter except) {
  do filter = TextureFilter((int(filter) + 1) % 3);
  while (filter == except);
  return filter;
}
