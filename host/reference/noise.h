// Ken Perlin's improved noise (SIGGRAPH 2002) in double precision: the CPU
// oracle of shaders/noise.glsl. The permutation table both sides share is data, in
// noise_permutation.h.
//
// - Lattice cell from floor (never int truncation), reduced mod 256: period 256.
// - Quintic fade 6t^5 - 15t^4 + 10t^3; gradients: the 12 cube-edge midpoints
//   (two components +-1, one 0), picked by the hash's low 4 bits, the last four
//   (h = 12..15) repeating (1,1,0), (0,-1,1), (-1,1,0), (0,-1,-1).
// - The permutation: noise_permutation.h.
#pragma once

#include "common.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>

// The most octaves turbulence()/dturbulence() sum (larger counts are clamped;
// octave 16 already has 65536x the base frequency): the kernel's NOISE_MAX_OCTAVES.
constexpr int kNoiseMaxOctaves = int(NOISE_MAX_OCTAVES);

// Improved Perlin noise. 0 at every integer lattice point; |value| < ~1.04.
double perlinNoise(glm::dvec3 p);

// x: perlinNoise(p); yzw: its analytic gradient d noise / d p (the fade's
// derivative is 30 t^2 (t - 1)^2). Exact up to rounding; no finite differences.
glm::dvec4 perlinNoiseGrad(glm::dvec3 p);

// sum_{i < octaves} |perlinNoise(p * 2^i)| / 2^i  (>= 0, < 2.1).
// octaves <= 0 gives 0; octaves > kNoiseMaxOctaves counts as kNoiseMaxOctaves.
double turbulence(glm::dvec3 p, int octaves);

// Derivative turbulence (Quilez's derivative fBm applied to turbulence):
//   D_i = sum_{j <= i} grad noise(p * 2^j)     (= the gradient of the partial fBm
//                                               sum_j noise(p 2^j) / 2^j w.r.t. p)
//   dturbulence = sum_{i < octaves} (|noise(p * 2^i)| / 2^i) / (1 + |D_i|^2)
// Octaves on steep slopes are damped: smooth valleys, rough crests. In [0, turbulence(p)].
double dturbulence(glm::dvec3 p, int octaves);
