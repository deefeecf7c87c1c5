// Ken Perlin's improved noise (SIGGRAPH 2002), its analytic gradient, turbulence
// and derivative turbulence, and (RAYTEX_FILTER_BOX) their frequency-clamped forms. The CPU
// double-precision oracle is host/reference/noise.cpp; keep the two in step.
//
// Needs (declared by the including kernel):
//   layout(std140, binding = BINDING_NOISE) uniform NoiseBlock { NoiseTable noiseTable; };
// holding the 256-entry permutation repeated to 512, in neighbour pairs (common.h, NoiseTable;
// host/reference/noise.cpp, fillNoiseTable).
//
// - Lattice cell from floor(), reduced mod 256 in float before any int conversion
//   (int() truncates toward 0 and breaks negative cells). Period 256.
// - Quintic fade 6t^5 - 15t^4 + 10t^3; 12 cube-edge gradients chosen by hash & 15
//   (slots 12..15 repeat (1,1,0), (0,-1,1), (-1,1,0), (0,-1,-1)).
// - float32: the fraction p - floor(p) keeps ~24 - log2|p| bits; far from the
//   origin reduce coordinates mod 256 on the host (docs/textures.md, "Noise").
#ifndef RAYTEX_NOISE_GLSL
#define RAYTEX_NOISE_GLSL

// perm[i] in the low 16 bits, perm[i + 1] in the high (i <= 510 here).
uint noisePermPair(uint i) { return noiseTable.pairs[i >> 2][i & 3u]; }

vec3 noiseFade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
vec3 noiseFadeDerivative(vec3 t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); }

// Finds the lattice cell of p: f = p - floor(p) and the hashes of its 8 corners,
// hLo for corners z = 0 ((0,0),(1,0),(0,1),(1,1) in x,y), hHi for z = 1.
void noiseCell(vec3 p, out vec3 f, out uvec4 hLo, out uvec4 hHi) {
  vec3 cell = floor(p);
  f = p - cell;
  uvec3 c = uvec3(mod(cell, 256.0)) & 255u;  // integer-valued floats: exact
  // Perlin's hashes, perm[perm[perm[x] + y] + z] for the 8 corners, from pairs: (perm[k],
  // perm[k + 1]) in one load. Indices stay below 511 (255 + 255 at most).
  uint px = noisePermPair(c.x);
  uint a = (px & 0xFFFFu) + c.y, b = (px >> 16) + c.y;
  uint pa = noisePermPair(a), pb = noisePermPair(b);
  uvec4 corners = uvec4(pa & 0xFFFFu, pb & 0xFFFFu, pa >> 16, pb >> 16) + c.z;  // aa, ba, ab, bb
  uvec4 h = uvec4(noisePermPair(corners.x), noisePermPair(corners.y), noisePermPair(corners.z),
                  noisePermPair(corners.w));
  hLo = h & 0xFFFFu;  // perm[aa], perm[ba], perm[ab], perm[bb]
  hHi = h >> 16;      // perm[aa + 1], ... : the z + 1 corners
}

// The gradient hash h & 15 selects: the 12 cube-edge midpoints, then (1,1,0), (0,-1,1),
// (-1,1,0), (0,-1,-1) again. Computed with selects, not a table: lavapipe is an order of
// magnitude slower with a dynamically indexed const vec3[16] (docs/performance.md, "Where the
// kernel's time goes").
vec3 noiseGradient(uint h) {
  h &= 15u;
  float su = (h & 1u) != 0u ? -1.0 : 1.0;  // sign of the first axis
  float sv = (h & 2u) != 0u ? -1.0 : 1.0;  // sign of the second axis
  bool vIsX = h == 12u || h == 14u;
  return vec3((h < 8u ? su : 0.0) + (vIsX ? sv : 0.0),
              (h >= 8u ? su : 0.0) + (h < 4u ? sv : 0.0),
              (h >= 4u && !vIsX) ? sv : 0.0);
}

// dot(noiseGradient(h), f) from selects of f's components, without forming the vector:
// fewer operations than the dot, and the same value (the gradients' components are 0 and +-1).
float noiseGradientDot(uint h, vec3 f) {
  h &= 15u;
  float u = h < 8u ? f.x : f.y;
  float v = h < 4u ? f.y : (h == 12u || h == 14u ? f.x : f.z);
  return ((h & 1u) == 0u ? u : -u) + ((h & 2u) == 0u ? v : -v);
}

// Improved Perlin noise; 0 at integer lattice points, |value| < ~1.04.
float perlinNoise(vec3 p) {
  vec3 f;
  uvec4 hLo, hHi;
  noiseCell(p, f, hLo, hHi);
  vec4 nLo = vec4(noiseGradientDot(hLo.x, f),
                  noiseGradientDot(hLo.y, f - vec3(1, 0, 0)),
                  noiseGradientDot(hLo.z, f - vec3(0, 1, 0)),
                  noiseGradientDot(hLo.w, f - vec3(1, 1, 0)));
  vec4 nHi = vec4(noiseGradientDot(hHi.x, f - vec3(0, 0, 1)),
                  noiseGradientDot(hHi.y, f - vec3(1, 0, 1)),
                  noiseGradientDot(hHi.z, f - vec3(0, 1, 1)),
                  noiseGradientDot(hHi.w, f - vec3(1, 1, 1)));
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

// sum_{i < octaves} |noise(p 2^i)| / 2^i. The octave loops are do-whiles: lavapipe runs a for
// loop's body once more, masked off, for the test at its top (trace.comp.glsl, main).
float turbulence(vec3 p, uint octaves) {
  float sum = 0.0, frequency = 1.0;
  uint n = min(octaves, NOISE_MAX_OCTAVES);
  if (n == 0u) return 0.0;
  uint i = 0u;
  do {
    sum += abs(perlinNoise(p * frequency)) / frequency;
    frequency *= 2.0;
  } while (++i < n);
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
  if (n == 0u) return 0.0;
  uint i = 0u;
  do {
    vec4 ng = perlinNoiseGrad(p * frequency);
    slope += ng.yzw;
    sum += abs(ng.x) / frequency / (1.0 + dot(slope, slope));
    frequency *= 2.0;
  } while (++i < n);
  return sum;
}

#ifdef RAYTEX_FILTER_BOX
// --- Frequency-clamped noise (FILTER_BOX; docs/textures.md, "Filtering the noise kinds"; pbrt
// FBm/Turbulence) ---
// `cells` is the width of a sample's footprint in lattice cells of the noise it filters
// (textures.glsl, noiseFootprintWidth); octave i of a sum sees cells * 2^i. An octave is
// replaced by the least-squares estimate of its average over the footprint given its value
// at the centre, mean + w (value - mean), with w = cov(box average, centre) / variance (an
// estimate from one sample: a footprint's average is not known). w is measured (docs/textures.md,
// "Filtering the noise kinds"): along a line L cells long, w = 0.94 (L = 0.5), 0.72 (1.1),
// 0.47 (1.9), 0.26 (3.2), ~0.8/L beyond for noise; 0.86, 0.52, 0.31, 0.18, ~0.6/L for |noise|.
// 1/sqrt(1 + (L/c)^2) fits both within 0.051; it is faded to 0 over one octave, from 2 to 4
// cells, where an octave is dropped: not evaluated, it adds its mean.

// Moments of perlinNoise over uniform random points of one period, [0, 256)^3, measured with
// host/reference/noise.cpp (two seeds of 10^7 points: E|n| = 0.22279 and 0.22276, Var|n| = 0.02504 and
// 0.02503; E n = 0). pbrt's Turbulence uses ~0.2 for its noise.
const float NOISE_ABS_MEAN = 0.2228;
const float NOISE_ABS_VARIANCE = 0.02503;
// c in 1/sqrt(1 + (L/c)^2), least-squares fits to the measured w (L from 0.1 to 7.6 cells).
const float NOISE_WEIGHT_CELLS = 1.05;      // noise
const float NOISE_ABS_WEIGHT_CELLS = 0.695;  // |noise| (turbulence octaves)
// An octave fades out from half this footprint width to this one, and is dropped beyond.
const float NOISE_DROP_CELLS = 4.0;

// The weight w of an octave (noise: c = NOISE_WEIGHT_CELLS; |noise|: NOISE_ABS_WEIGHT_CELLS)
// whose footprint spans `cells` lattice cells: 1 at 0 cells, 0 from NOISE_DROP_CELLS on (and
// for a NaN width).
float octaveWeight(float cells, float c) {
  if (!(cells < NOISE_DROP_CELLS)) return 0.0;
  float x = cells * (1.0 / c);
  return inversesqrt(1.0 + x * x) * (1.0 - smoothstep(0.5 * NOISE_DROP_CELLS, NOISE_DROP_CELLS, cells));
}

// turbulence(p, octaves) averaged over a footprint `cells` wide at the first octave. Octaves
// with weight w keep mean + w (|noise| - mean); from the first dropped one on, the rest add
// their means in closed form, so the octaves evaluated are those under NOISE_DROP_CELLS.
// `unresolved` returns the variance the footprint averages away, Var|n| sum_i (1 - w_i^2) / 4^i
// (w = 1: the point value, nothing lost), which marble and wood turn into contrast loss.
// cells = 0 gives turbulence(p, octaves).
float filteredTurbulence(vec3 p, uint octaves, float cells, out float unresolved) {
  float sum = 0.0, lost = 0.0, frequency = 1.0, amplitude = 1.0;
  uint n = min(octaves, NOISE_MAX_OCTAVES);
  uint i = 0u;
  if (n > 0u) do {  // a do-while, as in turbulence
    float w = octaveWeight(cells * frequency, NOISE_ABS_WEIGHT_CELLS);
    if (w <= 0.0) break;
    sum += (NOISE_ABS_MEAN + w * (abs(perlinNoise(p * frequency)) - NOISE_ABS_MEAN)) * amplitude;
    lost += (1.0 - w * w) * amplitude * amplitude;
    frequency *= 2.0;
    amplitude *= 0.5;
  } while (++i < n);
#ifdef RAYTEX_AOV
  keepOctavesPass(float(i));  // those evaluated; the rest add their means
#endif
  // The dropped octaves j = i..n-1 (amplitude = 2^-i): sum 2^-j = 2 (2^-i - 2^-n) and
  // sum 4^-j = 4/3 (4^-i - 4^-n).
  float end = exp2(-float(n));
  sum += NOISE_ABS_MEAN * 2.0 * (amplitude - end);
  lost += (4.0 / 3.0) * (amplitude * amplitude - end * end);
  unresolved = NOISE_ABS_VARIANCE * lost;
  return sum;
}

// The slope damping of dturbulence where m octaves up to this one are averaged away (their
// gradients unknown): Ea / e_m - 1, with e_m = E[|n_i| / (1 + |D_i|^2)] measured for all of
// octaves 0..i random (m = i + 1; 10^6 points: e = 0.1087, 0.0766, 0.0605, 0.0504, ...,
// 0.0182 for m = 1, 2, 3, 4, ..., 16). 1.047 m^0.852 fits Ea / e_m - 1 within 1 % of the fill.
float dturbulenceDamping(float m) { return m > 0.0 ? 1.047 * pow(m, 0.852) : 0.0; }

// dturbulence(p, octaves) averaged over a footprint `cells` wide at the first octave. Resolved
// octaves (weight w) add w times their gradient to the slope and keep mean + w (|noise| - mean);
// an averaged-away fraction 1 - w adds to m, and every octave is divided by
// 1 + |slope|^2 + dturbulenceDamping(m): with all octaves dropped that is exactly the measured
// mean of each octave. Dropped octaves evaluate no noise. cells = 0 gives dturbulence(p, octaves).
float filteredDturbulence(vec3 p, uint octaves, float cells) {
  float sum = 0.0, missing = 0.0, frequency = 1.0, amplitude = 1.0;
  vec3 slope = vec3(0.0);
#ifdef RAYTEX_AOV
  float kept = 0.0;  // octaves evaluated (w > 0)
#endif
  uint n = min(octaves, NOISE_MAX_OCTAVES);
  uint i = 0u;
  if (n > 0u) do {  // a do-while, as in turbulence
    float w = octaveWeight(cells * frequency, NOISE_ABS_WEIGHT_CELLS);
    float value = NOISE_ABS_MEAN;
    if (w > 0.0) {
#ifdef RAYTEX_AOV
      kept += 1.0;
#endif
      vec4 ng = perlinNoiseGrad(p * frequency);
      slope += w * ng.yzw;
      value += w * (abs(ng.x) - NOISE_ABS_MEAN);
    }
    missing += 1.0 - w;
    sum += value * amplitude / (1.0 + dot(slope, slope) + dturbulenceDamping(missing));
    frequency *= 2.0;
    amplitude *= 0.5;
  } while (++i < n);
#ifdef RAYTEX_AOV
  keepOctavesPass(kept);
#endif
  return sum;
}
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_NOISE_GLSL
