// CPU reference in double precision: camera rays and closest hits, written
// independently of the shaders, so image tests can check the GPU per pixel.
#pragma once

#include "bvh.h"
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

// A pinhole camera for an image size: its unit basis and half extents, worked out once for
// many rays.
struct ReferenceCamera {
  glm::dvec3 forward{0.0}, right{0.0}, up{0.0};
  double halfWidth = 0.0, halfHeight = 0.0;
  int width = 1, height = 1;
};
ReferenceCamera referenceCamera(const Camera& camera, int width, int height);

// Unit direction of the primary ray through pixel (x, y)'s centre + (dx, dy) in [-0.5, 0.5]:
// pinhole, vertical fov, aspect width/height, row 0 at the top.
glm::dvec3 referenceRayDirection(const ReferenceCamera& camera, int x, int y, double dx = 0.0,
                                 double dy = 0.0);
glm::dvec3 referenceRayDirection(const Camera& camera, int width, int height, int x, int y,
                                 double dx = 0.0, double dy = 0.0);

// Offset from the pixel centre of the centre of sub-cell s (0 .. n-1) of n per side, in
// [-0.5, 0.5]: the kernel's stratified sample positions.
inline double referenceSampleOffset(int s, int n) { return (s + 0.5) / n - 0.5; }

// The nearest hit along the ray. withTexCoords false leaves tc unset, for callers that need
// only what was hit and where (ray counting): the mappings' trigonometry is most of the cost.
// With bvh (buildSphereBvh of scene.spheres) only the spheres whose boxes the ray enters are
// tested, with the same result, except that edgeMargin then covers only those spheres.
ReferenceHit referenceClosestHit(const Scene& scene, glm::dvec3 origin, glm::dvec3 direction,
                                 bool withTexCoords = true, const SphereBvh* bvh = nullptr);
