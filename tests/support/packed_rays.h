// Rays through a packed scene (camera-relative, as the kernel sees it) traced in double, for the
// tests of the lists of spheres a shadow ray may meet (shadow_lists_test, shadow_grid_test).
#pragma once

#include "gpu_scene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

// The smallest t > 0 where the ray o + t d (d unit) meets the sphere, in double; infinity if none.
inline double sphereDistance(glm::dvec3 o, glm::dvec3 d, const gpu::Sphere& s) {
  const glm::dvec3 f = o - glm::dvec3(s.centerRadius);
  const double r = s.centerRadius.w, b = glm::dot(f, d), disc = b * b - (glm::dot(f, f) - r * r);
  if (disc < 0.0) return INFINITY;
  const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
  return t0 > 0.0 ? t0 : t1 > 0.0 ? t1 : INFINITY;
}

// Where the primary ray through a random point of pixel (x, y) of a w x h image first hits a
// sphere or plane of g, camera-relative; false where it hits nothing.
inline bool firstHit(const GpuScene& g, uint32_t x, uint32_t y, uint32_t w, uint32_t h, std::mt19937& rng,
                     glm::dvec3& point) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double fx = (x + unit(rng)) / w * 2.0 - 1.0, fy = 1.0 - (y + unit(rng)) / h * 2.0;
  const glm::dvec3 d = glm::normalize(glm::dvec3(g.frame.cameraForward) + fx * glm::dvec3(g.frame.cameraRight) +
                                      fy * glm::dvec3(g.frame.cameraUp));
  double t = INFINITY;
  for (const gpu::Sphere& s : g.spheres) t = std::min(t, sphereDistance({}, d, s));
  for (const gpu::Plane& p : g.planes) {
    const double tp = double(p.normalDistance.w) / glm::dot(glm::dvec3(p.normalDistance), d);
    if (tp > 0.0) t = std::min(t, tp);
  }
  point = t * d;
  return std::isfinite(t);
}
