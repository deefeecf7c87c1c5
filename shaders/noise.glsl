// Ken Perlin's improved noise (SIGGRAPH 2002), its analytic gradient, turbulence
// and derivative turbulence. The CPU double-precision oracle is host/noise.cpp;
// keep the two in step.
//
// Needs (declared by the including kernel):
//   layout(std140, binding = BINDING_NOISE) uniform NoiseBlock { NoiseTable noiseTable; };
// holding the 256-entry permutation repeated to 512 (host/noise.cpp, fillNoiseTable).
//
// - Lattice cell from floor(), reduced mod 256 in float before any int conversion
//   (int() truncates toward 0 and breaks negative cells; accuracy.md F1). Period 256.
// - Quintic fade 6t^5 - 15t^4 + 10t^3; 12 cube-edge gradients chosen by hash & 15
//   (slots 12..15 repeat (1,1,0), (0,-1,1), (-1,1,0), (0,-1,-1)).
// - float32: the fraction p - floor(p) keeps ~24 - log2|p| bits; far from the
//   origin reduce coordinates mod 256 on the host (accuracy.md F6).
#ifndef RAYTEX_NOISE_GLSL
#define RAYTEX_NOISE_GLSL

// Octave counts above this are clamped (kNoiseMaxOctaves in host/noise.h).
#define NOISE_MAX_OCTAVES 16u

uint noisePerm(uint i) { return noiseTable.perm[i >> 2][i & 3u]; }

vec3 noiseFade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
vec3 noiseFadeDerivative(vec3 t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); }

// Finds the lattice cell of p: f = p - floor(p) and the hashes of its 8 corners,
// hLo for corners z = 0 ((0,0),(1,0),(0,1),(1,1) in x,y), hHi for z = 1.
void noiseCell(vec3 p, out vec3 f, out uvec4 hLo, out uvec4 hHi) {
  vec3 cell = floor(p);
  f = p - cell;
  uvec3 c = uvec3(mod(cell, 256.0)) & 255u;  // integer-valued floats: exact
  uint a = noisePerm(c.x) + c.y, b = noisePerm(c.x + 1u) + c.y;
  uint aa = noisePerm(a) + c.z, ab = noisePerm(a + 1u) + c.z;
  uint ba = noisePerm(b) + c.z, bb = noisePerm(b + 1u) + c.z;
  hLo = uvec4(noisePerm(aa), noisePerm(ba), noisePerm(ab), noisePerm(bb));
  hHi = uvec4(noisePerm(aa + 1u), noisePerm(ba + 1u), noisePerm(ab + 1u), noisePerm(bb + 1u));
}

// The gradient hash h & 15 selects: the 12 cube-edge midpoints, then (1,1,0), (0,-1,1),
// (-1,1,0), (0,-1,-1) again. Computed with selects, not a table: with a dynamically
// indexed const vec3[16] the marble scene took 2.1 s at 320x240 on lavapipe, 0.16 s so.
vec3 noiseGradient(uint h) {
  h &= 15u;
  float su = (h & 1u) != 0u ? -1.0 : 1.0;  // sign of the first axis
  float sv = (h & 2u) != 0u ? -1.0 : 1.0;  // sign of the second axis
  bool vIsX = h == 12u || h == 14u;
  return vec3((h < 8u ? su : 0.0) + (vIsX ? sv : 0.0),
              (h >= 8u ? su : 0.0) + (h < 4u ? sv : 0.0),
              (h >= 4u && !vIsX) ? sv : 0.0);
}

// Improved Perlin noise; 0 at integer lattice points, |value| < ~1.04.
float perlinNoise(vec3 p) {
  vec3 f;
  uvec4 hLo, hHi;
  noiseCell(p, f, hLo, hHi);
  vec4 nLo = vec4(dot(noiseGradient(hLo.x), f),
                  dot(noiseGradient(hLo.y), f - vec3(1, 0, 0)),
                  dot(noiseGradient(hLo.z), f - vec3(0, 1, 0)),
                  dot(noiseGradient(hLo.w), f - vec3(1, 1, 0)));
  vec4 nHi = vec4(dot(noiseGradient(hHi.x), f - vec3(0, 0, 1)),
                  dot(noiseGradient(hHi.y), f - vec3(1, 0, 1)),
                  dot(noiseGradient(hHi.z), f - vec3(0, 1, 1)),
                  dot(noiseGradient(hHi.w), f - vec3(1, 1, 1)));
  vec3 u = noiseFade(f);
  vec4 nz = mix(nLo, nHi, u.z);          // (x0y0, x1y0, x0y1, x1y1)
  vec2 ny = mix(nz.xy, nz.zw, u.y);      // (x0, x1)
  return mix(ny.x, ny.y, u.x);
}

// x: perlinNoise(p), yzw: its analytic gradient. With the corner values n_i and
// faded weights (u, v, w), noise = k0 + k1 u + k2 v + k3 w + k4 uv + k5 vw + k6 wu
// + k7 uvw; the gradient differentiates both the corner values (d n_i/dp = g_i)
// and the weights (du/dx = 30 x^2 (x-1)^2).
vec4 perlinNoiseGrad(vec3 p) {
  vec3 f;
  uvec4 hLo, hHi;
  noiseCell(p, f, hLo, hHi);
  vec3 g0 = noiseGradient(hLo.x), g1 = noiseGradient(hLo.y);
  vec3 g2 = noiseGradient(hLo.z), g3 = noiseGradient(hLo.w);
  vec3 g4 = noiseGradient(hHi.x), g5 = noiseGradient(hHi.y);
  vec3 g6 = noiseGradient(hHi.z), g7 = noiseGradient(hHi.w);
  float n0 = dot(g0, f), n1 = dot(g1, f - vec3(1, 0, 0));
  float n2 = dot(g2, f - vec3(0, 1, 0)), n3 = dot(g3, f - vec3(1, 1, 0));
  float n4 = dot(g4, f - vec3(0, 0, 1)), n5 = dot(g5, f - vec3(1, 0, 1));
  float n6 = dot(g6, f - vec3(0, 1, 1)), n7 = dot(g7, f - vec3(1, 1, 1));
  vec3 u = noiseFade(f);
  vec3 du = noiseFadeDerivative(f);
  float k1 = n1 - n0, k2 = n2 - n0, k3 = n4 - n0;
  float k4 = n0 - n1 - n2 + n3, k5 = n0 - n2 - n4 + n6, k6 = n0 - n1 - n4 + n5;
  float k7 = -n0 + n1 + n2 - n3 + n4 - n5 - n6 + n7;
  float value = n0 + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z +
                k6 * u.z * u.x + k7 * u.x * u.y * u.z;
  vec3 grad = g0 + (g1 - g0) * u.x + (g2 - g0) * u.y + (g4 - g0) * u.z +
              (g0 - g1 - g2 + g3) * (u.x * u.y) + (g0 - g2 - g4 + g6) * (u.y * u.z) +
              (g0 - g1 - g4 + g5) * (u.z * u.x) +
              (-g0 + g1 + g2 - g3 + g4 - g5 - g6 + g7) * (u.x * u.y * u.z);
  grad += du * vec3(k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z,
                    k2 + k4 * u.x + k5 * u.z + k7 * u.x * u.z,
                    k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y);
  return vec4(value, grad);
}

// sum_{i < octaves} |noise(p 2^i)| / 2^i
float turbulence(vec3 p, uint octaves) {
  float sum = 0.0, frequency = 1.0;
  uint n = min(octaves, NOISE_MAX_OCTAVES);
  for (uint i = 0u; i < n; ++i) {
    sum += abs(perlinNoise(p * frequency)) / frequency;
    frequency *= 2.0;
  }
  return sum;
}

// Derivative turbulence (Quilez's derivative fBm applied to turbulence): octave i
// is divided by 1 + |D_i|^2, D_i = sum_{j <= i} grad noise(p 2^j) (the gradient of
// the partial fBm sum). Steep places lose their fine octaves: smooth valleys,
// rough crests. In [0, turbulence(p)].
float dturbulence(vec3 p, uint octaves) {
  float sum = 0.0, frequency = 1.0;
  vec3 slope = vec3(0.0);
  uint n = min(octaves, NOISE_MAX_OCTAVES);
  for (uint i = 0u; i < n; ++i) {
    vec4 ng = perlinNoiseGrad(p * frequency);
    slope += ng.yzw;
    sum += abs(ng.x) / frequency / (1.0 + dot(slope, slope));
    frequency *= 2.0;
  }
  return sum;
}

#endif  // RAYTEX_NOISE_GLSL
