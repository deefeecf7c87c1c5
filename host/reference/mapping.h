// Texture coordinates in double precision: the CPU oracle of shaders/mapping.glsl,
// following the course notes' equations directly (texture-mapping-notes eqs 1-9).
#pragma once

#include "plane_frame.h"
#include "scene.h"

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>


// A texture coordinate in every form a texture may want.
struct TexCoordD {
  glm::dvec2 uv;     // 2D coordinate in [0,1] (u across, v up the image)
  glm::dvec2 tile;   // index of the repeated tile (the floors of the unwrapped u, v); unplaced sphere: 0
  glm::dvec3 solid;  // 3D coordinate of solid textures: plane p / s, sphere (n + 1) / 2
  // Where an image is looked up (docs/textures.md, "Image orientation"): column and row as
  // fractions in [0, 1], column 0 at the image's left edge, row 0 at its top.
  glm::dvec2 image{0.0};
  glm::dvec2 imageTile{0.0};  // the floors of the unwrapped lookup (imageTile + image)
  bool clampV = false;  // image rows clamp at the sphere's poles instead of repeating
};

// R = Rz Ry Rx for rotations by degrees.x, .y, .z about the fixed x, y, z axes (right-handed).
glm::dmat3 placementRotation(glm::dvec3 degrees);

// The direction an image's top row points to on a plane of unit normal n, seen from the side n
// points to: world +y projected onto the plane, or -z projected where |n_y| >= sqrt(1/2). Unit.
glm::dvec3 imageUpAxis(glm::dvec3 n);

// Notes eqs (6), (1), (2): o' = d n, u_p = (p - o') . t, v_p = (p - o') . b,
// uv = (u_p/s - floor(u_p/s), v_p/s - floor(v_p/s)); tile = the floors; solid = p / s.
// uv may round to exactly 1.0 when u_p/s is a tiny negative number (as GLSL fract may):
// tile + uv is still the unwrapped coordinate, so checker parity stays right.
// Throws std::invalid_argument unless texScale > 0.
TexCoordD planeTexCoord(const PlaneFrame& frame, double texScale, glm::dvec3 p);

// The placed mapping (docs/textures.md, "Texture placement"): with o = d n, the mapping sees
// p' = R^-1 (p - o) + o on the plane through o with normal n' = R^-1 n, whose frame t', b' is
// planeFrame's for n'; u_p = (p' - o).t', v_p = (p' - o).b'; (u, v) unwrapped = (u_p, v_p) / s
// + (offset.x, offset.y); solid = p' / s + offset. image: the unwrapped (u, v) as the in-plane
// point W = u t' + v b', read along imageUpAxis(n') (top) and its right, up x n', then wrapped.
TexCoordD planeTexCoord(const PlaneFrame& frame, const TexturePlacement& placement, glm::dvec3 p);

// Notes eqs (7), (8), (9) for the unit normal n at a sphere hit (not normalised here):
//   phi = atan2(n_z, n_x), theta = asin(clamp(n_y, -1, 1)),
//   u = (phi + pi) / (2 pi), v = (theta + pi/2) / pi; tile = 0; solid = (n + 1) / 2.
// At the poles (n_x == n_z == 0) phi is defined as 0, so u = 0.5 (atan2(0, 0) is
// undefined in GLSL). On the -x meridian, u = 1 for n_z = +0 and u = 0 for n_z = -0
// (atan2's sign of zero; the GPU gives either, REPEAT makes them the same texel).
// The GLSL computes theta as atan(n_y, |n_xz|) (the same angle for a unit n; lavapipe's
// float asin is off by up to 2e-4 rad), see shaders/mapping.glsl.
// image = (1 - u, 1 - v): north up, unmirrored seen from outside; clampV is set.
TexCoordD sphereTexCoord(glm::dvec3 n);

// The placed mapping of a sphere: sphereTexCoord of n' = R^-1 n, its (u, v) divided by s and
// offset by (offset.x, offset.y), then wrapped (tile: the floors), its solid coordinate divided
// by s and offset by offset. v is left unwrapped and clamps at the poles (clampV) only while
// s = 1 and offset.y = 0.
TexCoordD sphereTexCoord(const TexturePlacement& placement, glm::dvec3 n);
