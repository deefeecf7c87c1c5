// The oracle of the passes (shaders/common.h, AOV_*): what the float64 reference sees through a
// pixel centre, for the pass tests (aov_test.cpp).
#pragma once

#include "image.h"
#include "reference.h"
#include "scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <map>
#include <string>

// What the primary ray through the centre of pixel (x, y) of a width x height image sees, in
// double: the oracle of the passes (common.h, AOV_*).
struct ReferencePasses {
  ReferenceHit hit;             // what the ray hit (kind 0: the background; every value below 0)
  double depth = 0.0;           // t along the unit direction from the eye
  glm::dvec3 position{0.0};     // world coordinates
  glm::dvec3 normal{0.0};       // unit, facing the eye
  glm::dvec3 coord{0.0};        // the solid coordinate for solid kinds, else (u, v, 0)
  glm::dvec3 albedo{0.0};       // the texture colour, point-sampled (k_d untextured)
  // Footprint widths along screen x and y (AOV_FOOTPRINT): the rays one pixel right and one
  // below meet the tangent plane at the hit dp away; each width is the change of the coordinate
  // above (unwrapped: tile + uv) between the surface points at -dp/2 and +dp/2 (on a sphere,
  // projected onto it): exact on planes, within O(|dp|^2) of the derivative on spheres.
  glm::dvec2 footprint{0.0};
};
ReferencePasses referencePasses(const Scene& scene, const std::map<std::string, ImageRGBA8>& images, int width,
                                int height, int x, int y);
