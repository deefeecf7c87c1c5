#include "plane_frame.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace {
bool isFinite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

PlaneFrame planeFrame(glm::dvec3 normal, double distance) {
  // Divide by the largest |component| first so that lengths like 1e-200 or 1e200
  // do not underflow or overflow when squared.
  const double largest = std::fmax(std::fabs(normal.x), std::fmax(std::fabs(normal.y), std::fabs(normal.z)));
  if (!isFinite(normal) || !std::isfinite(distance) || !(largest > 0.0))
    throw std::invalid_argument("plane normal must be finite and non-zero");
  const glm::dvec3 scaled = normal / largest;
  const double length = glm::length(scaled);
  PlaneFrame f;
  f.normal = scaled / length;
  f.distance = distance / largest / length;
  const glm::dvec3 n = f.normal;
  // Helper axis: +x unless n is within 45 degrees of the x axis, then +z.
  // Either way the projected helper has squared length >= 1/2.
  const glm::dvec3 helper = (2.0 * n.x * n.x <= 1.0) ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
  f.tangent = glm::normalize(helper - glm::dot(helper, n) * n);
  f.binormal = glm::normalize(glm::cross(f.tangent, n));
  return f;
}
