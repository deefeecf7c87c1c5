// CPU reference in double precision: camera rays and closest hits, written
// independently of the shaders, so image tests can check the GPU per pixel.
#pragma once

#include "mapping.h"
#include "scene.h"

#include <glm/vec3.hpp>

struct ReferenceHit {
  int kind = 0;    // 0 none, 1 plane, 2 sphere (HIT_* in common.h)
  int index = -1;  // into Scene::planes or Scene::spheres
  double t = 0.0;
  glm::dvec3 p{0.0};
  glm::dvec3 n{0.0};  // outward (sphere) or the plane's normal
  TexCoordD tc{};
  // How far the ray is from changing its answer: for a sphere, the distance of the
  // ray from the silhouette, relative to the radius; large away from edges.
  double edgeMargin = 1e30;
};

// Unit direction of the primary ray through pixel (x, y)'s centre + (dx, dy) in [-0.5, 0.5]:
// pinhole, vertical fov, aspect width/height, row 0 at the top.
glm::dvec3 referenceRayDirection(const Camera& camera, int width, int height, int x, int y,
                                 double dx = 0.0, double dy = 0.0);

ReferenceHit referenceClosestHit(const Scene& scene, glm::dvec3 origin, glm::dvec3 direction);
