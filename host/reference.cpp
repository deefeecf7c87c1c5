#include "reference.h"

#include <glm/geometric.hpp>

#include <cmath>

glm::dvec3 referenceRayDirection(const Camera& camera, int width, int height, int x, int y,
                                 double dx, double dy) {
  const glm::dvec3 eye(camera.eye), lookat(camera.lookat), upHint(camera.up);
  const glm::dvec3 w = glm::normalize(lookat - eye);
  const glm::dvec3 u = glm::normalize(glm::cross(w, upHint));
  const glm::dvec3 v = glm::cross(u, w);
  const double halfHeight = std::tan(double(camera.fovY) * M_PI / 360.0);
  const double halfWidth = halfHeight * double(width) / double(height);
  const double sx = ((x + 0.5 + dx) / width) * 2.0 - 1.0;
  const double sy = 1.0 - ((y + 0.5 + dy) / height) * 2.0;
  return glm::normalize(w + sx * halfWidth * u + sy * halfHeight * v);
}

ReferenceHit referenceClosestHit(const Scene& scene, glm::dvec3 o, glm::dvec3 d) {
  ReferenceHit best;
  best.t = INFINITY;
  // Spheres: |o + t d - c|^2 = r^2 with |d| = 1, textbook roots in double.
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& s = scene.spheres[i];
    const glm::dvec3 f = o - glm::dvec3(s.center);
    const double r = s.radius;
    const double b = glm::dot(f, d);
    const double disc = b * b - (glm::dot(f, f) - r * r);
    const double perpDistance = std::sqrt(std::max(glm::dot(f, f) - b * b, 0.0));
    const double margin = std::abs(perpDistance - r) / r;
    if (disc < 0.0) {
      best.edgeMargin = std::min(best.edgeMargin, margin);
      continue;
    }
    const double root = std::sqrt(disc);
    double t = -b - root;
    if (t <= 0.0) t = -b + root;
    if (t <= 0.0 || t >= best.t) continue;
    best = ReferenceHit{};
    best.kind = 2;
    best.index = int(i);
    best.t = t;
    best.n = glm::normalize(o + t * d - glm::dvec3(s.center));
    best.p = glm::dvec3(s.center) + r * best.n;
    best.tc = sphereTexCoord(best.n);
    best.edgeMargin = margin;
  }
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
    best.tc = planeTexCoord(frame, double(pl.texScale), best.p);
    best.edgeMargin = margin;  // a sphere passed nearby still makes this pixel an edge
  }
  if (best.kind == 0) best.t = 0.0;
  return best;
}
