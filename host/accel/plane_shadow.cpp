#include "plane_shadow.h"

#include "tile_lists.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

double paddedRadius(const gpu::Sphere& s, const glm::dvec3& light) {
  const glm::dvec3 c(s.centerRadius);
  const double r = s.centerRadius.w;
  return r + 1e-4 * (glm::length(c) + r + glm::length(light));
}

PlaneShadow planeShadow(const gpu::Sphere& s, const gpu::Plane& p, const glm::dvec3& light) {
  const glm::dvec3 n(p.normalDistance);
  const double lightHeight = glm::dot(n, light) - p.normalDistance.w;
  PlaneShadow out;
  out.extent = ShadowExtent::Unbounded;
  if (!(lightHeight != 0.0)) return out;
  glm::dvec3 corners[8];
  boundingCubeCorners(glm::dvec3(s.centerRadius), paddedRadius(s, light), corners);
  int beyond = 0, above = 0;
  for (int k = 0; k < 8; ++k) {
    const double height = glm::dot(n, corners[k]) - p.normalDistance.w;
    const double t = lightHeight / (lightHeight - height);  // the plane at light + t (corner - light)
    beyond += height * lightHeight < 0.0;
    if (!(t > 0.0 && std::isfinite(t))) ++above;
    else out.points[k] = light + t * (corners[k] - light);
  }
  if (beyond == 8 || above == 8) out.extent = ShadowExtent::None;
  else if (above == 0) out.extent = ShadowExtent::Bounded;
  return out;
}

std::vector<size_t> hullOrder(const std::vector<glm::dvec2>& points) {
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    return points[i].x < points[j].x || (points[i].x == points[j].x && points[i].y < points[j].y);
  });
  auto turn = [&](size_t o, size_t p, size_t q) {
    const glm::dvec2 a = points[p] - points[o], b = points[q] - points[o];
    return a.x * b.y - a.y * b.x;
  };
  std::vector<size_t> h(2 * order.size());
  size_t k = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], order[i]) <= 0.0) --k;
    h[k++] = order[i];
  }
  for (size_t i = order.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(h[k - 2], h[k - 1], order[i]) <= 0.0) --k;
    h[k++] = order[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

std::vector<glm::dvec3> hullOnPlane(const std::vector<glm::dvec3>& points, const glm::dvec3& n) {
  const glm::dvec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 b = glm::cross(n, t);  // (t, b) turns counter-clockwise about n
  std::vector<glm::dvec2> keys;
  for (const glm::dvec3& p : points) keys.emplace_back(glm::dot(p, t), glm::dot(p, b));
  std::vector<glm::dvec3> hull;
  for (size_t i : hullOrder(keys)) hull.push_back(points[i]);
  return hull;
}
