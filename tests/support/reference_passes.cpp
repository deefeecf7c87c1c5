#include "support/reference_passes.h"

#include "common.h"
#include "mapping.h"
#include "reference_render.h"
#include "texture_kinds.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace {

// The coordinate the pass reports at the surface point q of the hit's object (on a sphere, q
// projected onto it): unwrapped, so that differences across a tile border stay small.
glm::dvec3 passCoordAt(const Scene& scene, const ReferenceHit& hit, bool solid, glm::dvec3 q) {
  TexCoordD tc;
  if (hit.kind == HIT_PLANE) {
    const Plane& pl = scene.planes[size_t(hit.index)];
    tc = planeTexCoord(planeFrame(glm::dvec3(pl.normal), double(pl.distance)), pl.placement, q);
  } else {
    const Sphere& s = scene.spheres[size_t(hit.index)];
    tc = sphereTexCoord(s.placement, glm::normalize(q - glm::dvec3(s.center)));
  }
  return solid ? tc.solid : glm::dvec3(tc.tile + tc.uv, 0.0);
}

// The footprint width along the step to the ray `next` (AOV_FOOTPRINT): see ReferencePasses.
double footprintWidth(const Scene& scene, const ReferencePasses& r, bool solid, glm::dvec3 eye, glm::dvec3 next) {
  const glm::dvec3 n = r.hit.n;
  const glm::dvec3 dp = eye + glm::dot(n, r.hit.p - eye) / glm::dot(n, next) * next - r.hit.p;
  glm::dvec3 d = passCoordAt(scene, r.hit, solid, r.hit.p + 0.5 * dp) - passCoordAt(scene, r.hit, solid, r.hit.p - 0.5 * dp);
  if (!solid && r.hit.kind == HIT_SPHERE) d.x -= std::round(d.x);  // across u's seam
  return glm::length(d);
}

}  // namespace

ReferencePasses referencePasses(const Scene& scene, const std::map<std::string, ImageRGBA8>& images, int width,
                                int height, int x, int y) {
  const ReferenceCamera camera = referenceCamera(scene.camera, width, height);
  const glm::dvec3 eye(scene.camera.eye), d = referenceRayDirection(camera, x, y);
  ReferencePasses r;
  r.hit = referenceClosestHit(scene, eye, d);
  if (r.hit.kind == 0) return r;
  const Material fallback = defaultMaterial();
  const Material& m = materialAt(scene, r.hit.kind == HIT_PLANE ? scene.planes[size_t(r.hit.index)].material
                                                                : scene.spheres[size_t(r.hit.index)].material,
                                 fallback);
  const bool solid = isSolidTexture(m.texture.kind);
  r.depth = r.hit.t;
  r.position = r.hit.p;
  r.normal = glm::dot(r.hit.n, d) > 0.0 ? -r.hit.n : r.hit.n;
  r.coord = solid ? r.hit.tc.solid : glm::dvec3(r.hit.tc.uv, 0.0);
  r.albedo = referenceAlbedo(images, m, r.hit);
  r.footprint = {footprintWidth(scene, r, solid, eye, referenceRayDirection(camera, x, y, 1.0, 0.0)),
                 footprintWidth(scene, r, solid, eye, referenceRayDirection(camera, x, y, 0.0, 1.0))};
  return r;
}
