// The in-plane axes (u, v) of a plane's texture: a convention the GPU path (gpu_scene.cpp packs
// the frame) and the double-precision oracle (mapping.cpp) must share, like the noise
// permutation, so it is defined once here. No Vulkan.
#pragma once

#include <glm/vec3.hpp>

// The texture frame of the plane x . normal = distance.
//
// Basis rule (planeFrame): n = normalize(normal);
//   helper h = +x if n_x^2 <= 1/2, else +z        (|n_x| > 1/sqrt(2): n is within 45 deg of +-x)
//   tangent  t = normalize(h - (h . n) n)          (h projected onto the plane; |h - (h.n)n|^2 >= 1/2,
//                                                    so it is defined, finite and well conditioned for
//                                                    EVERY unit normal: no cross(n, up) singularity)
//   binormal b = t x n                              (so (t, n, b) is right-handed like (x, y, z))
// For n = (0,1,0): t = +x, b = x X y = +z exactly (u runs along x, v along z on the floor).
// Other examples: n = (0,-1,0): t = +x, b = -z; n = (0,0,+-1): t = +x, b = -+y;
// n = (+-1,0,0): t = +z, b = +-y.
// The host uploads this frame (gpu::Plane.tangentScale / binormal); the GPU never builds one.
struct PlaneFrame {
  glm::dvec3 normal;    // unit
  glm::dvec3 tangent;   // unit, orthogonal to normal
  glm::dvec3 binormal;  // unit, = tangent x normal
  double distance;      // the plane is x . normal = distance (after normalising)
};

// Throws std::invalid_argument if normal is zero or not finite. A non-unit normal is
// normalised and `distance` divided by its length, so the plane stays the same.
PlaneFrame planeFrame(glm::dvec3 normal, double distance);
