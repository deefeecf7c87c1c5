// The scenes of the stability suite (tests/stability_*_test.cpp), built in code: one builder
// per numerically hard case, shared so that the supersampled and filtered sweep renders every
// scene again.
#pragma once

#include "scene.h"
#include "texture.h"
#include "texture_kinds.h"

#include "support/files.h"
#include "support/format.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

constexpr double kPi = 3.14159265358979323846;

// A scene with a background no texture or shading here produces, a white ambient light
// and no objects.
inline Scene emptyScene() {
  Scene scene;
  scene.path = kSourceDir + "/tests/support/stability_scenes.h";
  scene.background = glm::vec3(0.25f, 0.5f, 0.75f);
  scene.ambientLight = glm::vec3(1.0f);
  return scene;
}

// Adds a material (the default Phong one, textured with `kind`'s defaults unless None).
inline int addMaterial(Scene& scene, TextureKind kind) {
  Material m = defaultMaterial();
  m.name = std::string("m") + std::to_string(scene.materials.size());
  if (kind != TextureKind::None) m.texture = defaultTexture(kind);
  if (kind == TextureKind::Image) m.texture.imagePath = kSourceDir + "/textures/uv_grid.png";
  scene.materials.push_back(m);
  return int(scene.materials.size()) - 1;
}

inline void addSphere(Scene& scene, glm::dvec3 center, double radius, int material) {
  Sphere s;
  s.center = center;
  s.radius = radius;
  s.material = material;
  scene.spheres.push_back(s);
}

inline void addPlane(Scene& scene, glm::dvec3 normal, double distance, double texScale, int material) {
  Plane p;
  p.normal = normal;
  p.distance = distance;
  p.placement.scale = texScale;
  p.material = material;
  scene.planes.push_back(p);
}

inline void addLight(Scene& scene, glm::dvec3 position) {
  Light l;
  l.position = position;
  l.color = glm::vec3(1.0f);
  scene.lights.push_back(l);
}

inline void setCamera(Scene& scene, glm::dvec3 eye, glm::dvec3 lookat, glm::dvec3 up, double fovY) {
  scene.camera.eye = eye;
  scene.camera.lookat = lookat;
  scene.camera.up = up;
  scene.camera.fovY = fovY;
}

inline double degrees(double radians) { return radians * 180.0 / kPi; }

// --- the scenes ----------------------------------------------------------------
// One builder per case, so that the sweep (stability_sampling_sweep_test.cpp) can render every
// scene again with supersampling and texture filtering.

// 1. Unit checks (tex_scale 1, one check per tile) on y = 0 seen straight from above at
// height 10, the view centred at (0.5, 0.3): 120 rows = 6 units (tan(fov/2) = 0.3), so at
// 160 x 120 a check is 20 px wide and its edges fall on pixel borders. Image x runs along
// +x, rows along +z.
inline Scene checkerFloorScene() {
  Scene scene = emptyScene();
  int checker = addMaterial(scene, TextureKind::Checker);
  scene.materials[size_t(checker)].texture.squares = 1.0f;
  addPlane(scene, {0, 1, 0}, 0.0f, 1.0f, checker);
  addLight(scene, {0.5f, 10.0f, 0.3f});
  setCamera(scene, {0.5f, 10.0f, 0.3f}, {0.5f, 0.0f, 0.3f}, {0, 0, -1}, degrees(2.0 * std::atan(0.3)));
  return scene;
}

// 2. Straight down the axis of a sphere of radius 2 from height 10; the disc (angular
// radius asin(0.2)) spans ~80 % of the image height.
inline Scene poleScene(TextureKind kind) {
  Scene scene = emptyScene();
  addSphere(scene, {0, 0, 0}, 2.0f, addMaterial(scene, kind));
  addLight(scene, {4.0f, 12.0f, 3.0f});
  setCamera(scene, {0, 10, 0}, {0, 0, 0}, {0, 0, -1}, degrees(2.0 * std::atan(0.25)));
  return scene;
}

// 3. Inside a sphere of radius 5 centred at the origin, looking towards its u seam
// (phi = +-pi), a light inside.
inline Scene insideScene(glm::vec3 eye, TextureKind kind) {
  Scene scene = emptyScene();
  addSphere(scene, {0, 0, 0}, 5.0f, addMaterial(scene, kind));
  addLight(scene, eye + glm::vec3(0.5f, 1.0f, 0.3f));
  setCamera(scene, eye, eye + glm::vec3(-1.0f, 0.3f, 0.2f), {0, 1, 0}, 90.0);
  return scene;
}

// 4. The eye `height` above the plane y = 0, looking horizontally (forward.y = 0 and
// up = +y exactly), a sphere standing on the plane ahead.
inline Scene onPlaneScene(float height) {
  Scene scene = emptyScene();
  addPlane(scene, {0, 1, 0}, 0.0f, 1.0f, addMaterial(scene, TextureKind::Checker));
  addSphere(scene, {0.5f, 1.0f, -6.0f}, 1.0f, addMaterial(scene, TextureKind::SolidChecker));
  addLight(scene, {3.0f, 6.0f, 2.0f});
  setCamera(scene, {0, height, 0}, {0, height, -1}, {0, 1, 0}, 40.0);
  return scene;
}

// 5. A sphere of radius r at distance D (slightly off the view axis); the field of view
// makes the disc radius a third of the image half-height: tan(fov/2) = 3 tan(asin(r/D)).
inline Scene smallSphereScene(double r, double distance) {
  Scene scene = emptyScene();
  addSphere(scene, {float(0.37 * r), float(0.21 * r), float(-distance)}, float(r),
            addMaterial(scene, TextureKind::SolidChecker));
  addLight(scene, {0, 0, 0});
  setCamera(scene, {0, 0, 0}, {0, 0, -1}, {0, 1, 0},
            degrees(2.0 * std::atan(3.0 * std::tan(std::asin(r / distance)))));
  return scene;
}

// 6. A unit sphere resting on the checker plane y = 0, a light at a grazing angle (1.2
// up, ~9 away), everything (camera, light, sizes, tex_scale) times `scale`. Checker
// colours 0.9 / 0.3 on the plane, the solid checker's 0.9 / 0.1 on the sphere.
inline Scene acneScene(float scale) {
  Scene scene = emptyScene();
  int planeMat = addMaterial(scene, TextureKind::Checker);
  int sphereMat = addMaterial(scene, TextureKind::SolidChecker);
  scene.materials[size_t(planeMat)].texture.color1 = glm::vec3(0.9f);
  scene.materials[size_t(planeMat)].texture.color2 = glm::vec3(0.3f);
  addPlane(scene, {0, 1, 0}, 0.0f, scale, planeMat);
  addSphere(scene, glm::vec3(0, 1, 0) * scale, scale, sphereMat);
  addLight(scene, glm::vec3(8.0f, 1.2f, 3.0f) * scale);
  setCamera(scene, glm::vec3(4, 6, 9) * scale, glm::vec3(-3, 0, -1) * scale, {0, 1, 0}, 50.0);
  return scene;
}

// 7. Scenes the parser rejects or that put rays and lights on singular points, for an
// odd-sized image (the centre pixel's ray is exactly the view axis): a zero-radius sphere
// and one whose r^2 underflows, each hit dead centre (normalize(0)); lights exactly on
// the plane, on the sphere and at a shaded point; planes with axis normals and a
// near-parallel one (tangent frames built from a helper axis).
struct NamedScene {
  std::string name;
  Scene scene;
};

inline std::vector<NamedScene> degenerateScenes() {
  std::vector<NamedScene> scenes;
  auto base = [](glm::vec3 eye, glm::vec3 lookat) {
    Scene s = emptyScene();
    setCamera(s, eye, lookat, {0, 1, 0}, 40.0);
    return s;
  };
  for (float radius : {0.0f, 1e-30f}) {
    Scene s = base({0, 1, 10}, {0, 1, 0});  // the centre ray passes through (0, 1, 0)
    addSphere(s, {0, 1, 0}, radius, addMaterial(s, TextureKind::SolidChecker));
    addSphere(s, {2, 1, -1}, 1.0f, addMaterial(s, TextureKind::Checker));
    addPlane(s, {0, 1, 0}, 0.0f, 1.0f, addMaterial(s, TextureKind::Checker));
    addLight(s, {0, 5, 10});
    scenes.push_back({"sphere radius " + fmtG(radius), s});
  }
  {
    Scene s = base({3, 4, 6}, {0, 0.5f, 0});
    addPlane(s, {0, 1, 0}, 0.0f, 1.0f, addMaterial(s, TextureKind::Checker));
    addSphere(s, {0, 1, 0}, 1.0f, addMaterial(s, TextureKind::SolidChecker));
    addLight(s, {2, 0, 1});
    scenes.push_back({"light on the plane", s});
  }
  {
    Scene s = base({3, 4, 6}, {0, 0.5f, 0});
    addPlane(s, {0, 1, 0}, 0.0f, 1.0f, addMaterial(s, TextureKind::Checker));
    addSphere(s, {0, 1, 0}, 1.0f, addMaterial(s, TextureKind::SolidChecker));
    addLight(s, {0, 2, 0});
    addLight(s, {1, 1, 0});
    scenes.push_back({"lights on the sphere", s});
  }
  {
    Scene s = base({0, 5, 5}, {0, 0, 0});  // the centre ray meets the plane at the light
    addPlane(s, {0, 1, 0}, 0.0f, 1.0f, addMaterial(s, TextureKind::Checker));
    addLight(s, {0, 0, 0});
    scenes.push_back({"light at a shaded point", s});
  }
  const glm::vec3 normals[] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0},
                               {0, 0, 1}, {0, 0, -1}, {1e-7f, 1, 0}};
  for (const glm::vec3& n : normals) {
    Scene s = base({6, 7, 8}, {0, 0, 0});
    addPlane(s, n, 0.0f, 1.0f, addMaterial(s, TextureKind::Checker));
    addSphere(s, {-1, -1, -1}, 0.5f, addMaterial(s, TextureKind::SolidChecker));
    addLight(s, {5, 5, 5});
    addLight(s, {-5, -5, -5});
    scenes.push_back({"plane normal (" + fmtG(n.x) + ", " + fmtG(n.y) + ", " + fmtG(n.z) + ")", s});
  }
  return scenes;
}

// 8. The checker plane y = 0 and a unit sphere standing on it at x = X, seen from 7 units
// away with the horizon in view, the camera and the light translated with them; `placed`:
// with textures turned about the y axis, scaled and offset (the sphere's poles stay at +-y).
inline Scene farScene(double X, bool placed = false) {
  const glm::dvec3 at(X, 0.0, 0.0);
  Scene scene = emptyScene();
  addPlane(scene, {0, 1, 0}, 0.0f, 1.0f, addMaterial(scene, TextureKind::Checker));
  addSphere(scene, at + glm::dvec3(0, 1, 0), 1.0, addMaterial(scene, TextureKind::Checker));
  if (placed) {
    scene.planes[0].placement = {{0, 33, 0}, 1.3, {0.2, 0.7, 0}};
    scene.spheres[0].placement = {{0, -50, 0}, 0.6, {0.35, 0.15, 0}};
  }
  addLight(scene, at + glm::dvec3(3, 8, 2));
  setCamera(scene, at + glm::dvec3(2, 3, 6), at + glm::dvec3(0, 0.5, 0), {0, 1, 0}, 50.0);
  return scene;
}
