// Yardstick 2: the course scene with aChecker on the sphere (raytex's textures.cfg with
// "aChecker;" in the sphere block): a 2D checker on the plane, the latitude/longitude checker on
// the sphere (2 x 2 checks over the map), Phong and one shadow ray per hit. Scene constants are
// hard-coded (course_scene.glsl). Compiled at build time (CMakeLists.txt, add_spirv).
#version 460
#extension GL_GOOGLE_include_directive : require

const float SPHERE_KS = 0.1;  // aChecker
const float SPHERE_SHININESS = 20.0;

#include "course_scene.glsl"

// u = (atan(n_z, n_x) + pi) / 2pi, v = (asin(n_y) + pi/2) / pi (course notes eqs 7, 8).
vec3 sphereAlbedo(vec3 n) {
  vec2 uv = vec2((atan(n.z, n.x) + PI) / (2.0 * PI), (asin(clamp(n.y, -1.0, 1.0)) + 0.5 * PI) / PI);
  vec2 cell = floor(uv * CHECKER_SQUARES);
  return mod(cell.x + cell.y, 2.0) < 0.5 ? CHECKER_COLOR1 : CHECKER_COLOR2;
}
