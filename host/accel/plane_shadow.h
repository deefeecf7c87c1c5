// A sphere's shadow on a plane from a point light, for the lists of spheres a shadow ray may
// meet (shadow_lists.h, shadow_grid.h): the plane's points from which the segment to the light
// meets the sphere lie in the projection of its padded bounding cube from the light onto the
// plane, the hull of the 8 projected corners. Camera-relative values, in double. No Vulkan.
#pragma once

#include "common.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

// A sphere's radius grown by 1e-4 of its size and its distances from the camera and the light:
// far beyond the float rounding of the kernel's hit points, shadow-ray origins and sphere test.
double paddedRadius(const gpu::Sphere& s, const glm::dvec3& light);

enum class ShadowExtent {
  None,       // the sphere lies wholly beyond the plane: it shades no point on the light's side
  Bounded,    // in the hull of `points`
  Unbounded,  // the sphere reaches the light's height above the plane (or the light is on it)
};

struct PlaneShadow {
  ShadowExtent extent = ShadowExtent::None;
  glm::dvec3 points[8];  // Bounded: the padded cube's corners projected onto the plane
};

// The shadow of sphere s on plane p from the light at `light`.
PlaneShadow planeShadow(const gpu::Sphere& s, const gpu::Plane& p, const glm::dvec3& light);

// The indices of the convex hull of 2D points, counter-clockwise (monotone chain).
std::vector<size_t> hullOrder(const std::vector<glm::dvec2>& points);

// The convex hull of points on the plane of unit normal n, in order.
std::vector<glm::dvec3> hullOnPlane(const std::vector<glm::dvec3>& points, const glm::dvec3& n);
