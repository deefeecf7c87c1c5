// Yardstick 3 (and 4 with -DSAMPLES_PER_SIDE=2): the course scene with marble on the sphere,
// aMarble's texture with 8 octaves (raytex's side overrides aMarble's default 6, so both do the
// same work): t = ((1 + sin(pi (q_x + q_y) + strength turbulence(q))) / 2)^3, q = scale (n + 1)/2,
// colour mix(color1, color2, t); classic improved Perlin noise (Perlin 2002) on the
// permutation table in a uniform buffer. Floor, shading and shadows as checker.comp
// (course_scene.glsl). Compiled at build time (CMakeLists.txt, add_spirv).
#version 460
#extension GL_GOOGLE_include_directive : require

const float SPHERE_KS = 0.5;  // aMarble
const float SPHERE_SHININESS = 64.0;

#include "course_scene.glsl"

// The marble kind's defaults (host/reference/texture.cpp), aMarble setting none of them.
const vec3 MARBLE_COLOR1 = vec3(0.9, 0.88, 0.85);
const vec3 MARBLE_COLOR2 = vec3(0.15, 0.12, 0.2);
const float MARBLE_SCALE = 4.0;
const float MARBLE_STRENGTH = 6.0;
const int OCTAVES = 8;

// The 256-entry permutation repeated to 512, four to a uvec4 (std140 pads scalar arrays).
layout(std140, binding = 1) uniform PermutationBlock { uvec4 permutation[128]; };

uint perm(uint i) { return permutation[i >> 2][i & 3u]; }

// The dot of p with the gradient hash h picks: 12 cube-edge directions (h = 12..15 repeat four).
float grad(uint h, vec3 p) {
  h &= 15u;
  float u = h < 8u ? p.x : p.y;
  float v = h < 4u ? p.y : (h == 12u || h == 14u ? p.x : p.z);
  return ((h & 1u) == 0u ? u : -u) + ((h & 2u) == 0u ? v : -v);
}

float noise(vec3 p) {
  vec3 cell = floor(p);
  vec3 f = p - cell;
  uvec3 c = uvec3(ivec3(cell) & 255);
  vec3 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  uint a = perm(c.x) + c.y, aa = perm(a) + c.z, ab = perm(a + 1u) + c.z;
  uint b = perm(c.x + 1u) + c.y, ba = perm(b) + c.z, bb = perm(b + 1u) + c.z;
  return mix(mix(mix(grad(perm(aa), f), grad(perm(ba), f - vec3(1, 0, 0)), w.x),
                 mix(grad(perm(ab), f - vec3(0, 1, 0)), grad(perm(bb), f - vec3(1, 1, 0)), w.x), w.y),
             mix(mix(grad(perm(aa + 1u), f - vec3(0, 0, 1)), grad(perm(ba + 1u), f - vec3(1, 0, 1)), w.x),
                 mix(grad(perm(ab + 1u), f - vec3(0, 1, 1)), grad(perm(bb + 1u), f - vec3(1, 1, 1)), w.x), w.y),
             w.z);
}

float turbulence(vec3 p) {
  float sum = 0.0, frequency = 1.0;
  for (int i = 0; i < OCTAVES; ++i) {
    sum += abs(noise(p * frequency)) / frequency;
    frequency *= 2.0;
  }
  return sum;
}

vec3 sphereAlbedo(vec3 n) {
  vec3 q = (n + 1.0) * 0.5 * MARBLE_SCALE;
  float s = 0.5 + 0.5 * sin(PI * (q.x + q.y) + MARBLE_STRENGTH * turbulence(q));
  return mix(MARBLE_COLOR1, MARBLE_COLOR2, s * s * s);
}
