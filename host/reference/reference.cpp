#include "reference.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

ReferenceCamera referenceCamera(const Camera& camera, int width, int height) {
  const glm::dvec3 eye(camera.eye), lookat(camera.lookat), upHint(camera.up);
  ReferenceCamera c;
  c.forward = glm::normalize(lookat - eye);
  c.right = glm::normalize(glm::cross(c.forward, upHint));
  c.up = glm::cross(c.right, c.forward);
  c.halfHeight = std::tan(double(camera.fovY) * M_PI / 360.0);
  c.halfWidth = c.halfHeight * double(width) / double(height);
  c.width = width;
  c.height = height;
  return c;
}

glm::dvec3 referenceRayDirection(const ReferenceCamera& c, int x, int y, double dx, double dy) {
  const double sx = ((x + 0.5 + dx) / c.width) * 2.0 - 1.0;
  const double sy = 1.0 - ((y + 0.5 + dy) / c.height) * 2.0;
  return glm::normalize(c.forward + sx * c.halfWidth * c.right + sy * c.halfHeight * c.up);
}

glm::dvec3 referenceRayDirection(const Camera& camera, int width, int height, int x, int y,
                                 double dx, double dy) {
  return referenceRayDirection(referenceCamera(camera, width, height), x, y, dx, dy);
}

ReferenceHit referenceClosestHit(const Scene& scene, glm::dvec3 o, glm::dvec3 d, bool withTexCoords,
                                 const SphereBvh* bvh) {
  ReferenceHit best;
  best.t = INFINITY;
  // Spheres: |o + t d - c|^2 = r^2 with |d| = 1, textbook roots in double.
  auto sphere = [&](uint32_t i) {
    const Sphere& s = scene.spheres[i];
    const glm::dvec3 f = o - glm::dvec3(s.center);
    const double r = s.radius;
    const double b = glm::dot(f, d);
    const double disc = b * b - (glm::dot(f, f) - r * r);
    const double perpDistance = std::sqrt(std::max(glm::dot(f, f) - b * b, 0.0));
    const double margin = std::abs(perpDistance - r) / r;
    if (disc < 0.0) {
      best.edgeMargin = std::min(best.edgeMargin, margin);
      return;
    }
    const double root = std::sqrt(disc);
    double t = -b - root;
    if (t <= 0.0) t = -b + root;
    if (t <= 0.0 || t >= best.t) return;
    best = ReferenceHit{};
    best.kind = 2;
    best.index = int(i);
    best.t = t;
    best.n = glm::normalize(o + t * d - glm::dvec3(s.center));
    best.p = glm::dvec3(s.center) + r * best.n;
    if (withTexCoords) best.tc = sphereTexCoord(s.placement, best.n);
    best.edgeMargin = margin;
  };
  if (bvh)
    visitSpheresAlong(*bvh, o, d, best.t, sphere);
  else
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) sphere(i);
  for (size_t i = 0; i < scene.planes.size(); ++i) {
    const Plane& pl = scene.planes[i];
    const PlaneFrame frame = planeFrame(glm::dvec3(pl.normal), double(pl.distance));
    const double denom = glm::dot(frame.normal, d);
    if (denom == 0.0) continue;
    const double t = (frame.distance - glm::dot(frame.normal, o)) / denom;
    if (!(t > 0.0 && t < best.t)) continue;
    const double margin = best.edgeMargin;
    best = ReferenceHit{};
    best.kind = 1;
    best.index = int(i);
    best.t = t;
    best.p = o + t * d;
    best.n = frame.normal;
    if (withTexCoords) best.tc = planeTexCoord(frame, pl.placement, best.p);
    best.edgeMargin = margin;  // a sphere passed nearby still makes this pixel an edge
  }
  if (best.kind == 0) best.t = 0.0;
  return best;
}
