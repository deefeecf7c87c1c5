#include "noise.h"

#include "noise_permutation.h"

#include "common.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace {

// 12 cube-edge midpoints, then 4 repeats (as in Perlin 2002) to fill 16 slots.
const glm::dvec3 kGradients[16] = {
    {1, 1, 0},  {-1, 1, 0},  {1, -1, 0}, {-1, -1, 0},  // xy edges
    {1, 0, 1},  {-1, 0, 1},  {1, 0, -1}, {-1, 0, -1},  // xz edges
    {0, 1, 1},  {0, -1, 1},  {0, 1, -1}, {0, -1, -1},  // yz edges
    {1, 1, 0},  {0, -1, 1},  {-1, 1, 0}, {0, -1, -1},  // repeats
};

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double fadeDerivative(double t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); }

// floor(x) mod 256 in [0, 255], exact for any finite double (no int overflow).
uint32_t latticeIndex(double cell) {
  double r = cell - 256.0 * std::floor(cell / 256.0);
  return static_cast<uint32_t>(r) & 255u;
}

// The lattice cell containing p: the fractional position in it and the hashes
// of its 8 corners, h[i] for corner (i & 1, (i >> 1) & 1, (i >> 2) & 1).
struct NoiseCell {
  glm::dvec3 f;
  uint32_t h[8];
};

NoiseCell noiseCell(glm::dvec3 p) {
  const std::array<uint32_t, 512>& P = noisePermutation();
  glm::dvec3 cell = glm::floor(p);
  NoiseCell c;
  c.f = p - cell;
  uint32_t X = latticeIndex(cell.x), Y = latticeIndex(cell.y), Z = latticeIndex(cell.z);
  // P[P[P[x] + y] + z] with x, y, z in [0, 256]; all indices stay below 512.
  uint32_t a = P[X] + Y, b = P[X + 1] + Y;
  uint32_t aa = P[a] + Z, ab = P[a + 1] + Z, ba = P[b] + Z, bb = P[b + 1] + Z;
  c.h[0] = P[aa];
  c.h[1] = P[ba];
  c.h[2] = P[ab];
  c.h[3] = P[bb];
  c.h[4] = P[aa + 1];
  c.h[5] = P[ba + 1];
  c.h[6] = P[ab + 1];
  c.h[7] = P[bb + 1];
  return c;
}

glm::dvec3 cornerOffset(int i) { return glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); }

int clampOctaves(int octaves) { return octaves < 0 ? 0 : (octaves > kNoiseMaxOctaves ? kNoiseMaxOctaves : octaves); }

}  // namespace

double perlinNoise(glm::dvec3 p) {
  NoiseCell c = noiseCell(p);
  double n[8];
  for (int i = 0; i < 8; ++i) n[i] = glm::dot(kGradients[c.h[i] & 15u], c.f - cornerOffset(i));
  double u = fade(c.f.x), v = fade(c.f.y), w = fade(c.f.z);
  // Trilinear interpolation of the corner values with the faded weights.
  double x00 = n[0] + u * (n[1] - n[0]);
  double x10 = n[2] + u * (n[3] - n[2]);
  double x01 = n[4] + u * (n[5] - n[4]);
  double x11 = n[6] + u * (n[7] - n[6]);
  double y0 = x00 + v * (x10 - x00);
  double y1 = x01 + v * (x11 - x01);
  return y0 + w * (y1 - y0);
}

glm::dvec4 perlinNoiseGrad(glm::dvec3 p) {
  NoiseCell c = noiseCell(p);
  glm::dvec3 g[8];
  double n[8];
  for (int i = 0; i < 8; ++i) {
    g[i] = kGradients[c.h[i] & 15u];
    n[i] = glm::dot(g[i], c.f - cornerOffset(i));
  }
  double u = fade(c.f.x), v = fade(c.f.y), w = fade(c.f.z);
  double du = fadeDerivative(c.f.x), dv = fadeDerivative(c.f.y), dw = fadeDerivative(c.f.z);
  // noise = k0 + k1 u + k2 v + k3 w + k4 uv + k5 vw + k6 wu + k7 uvw, where the
  // k's are combinations of the corner values n_i(p) = g_i . (f - c_i).
  double k0 = n[0];
  double k1 = n[1] - n[0];
  double k2 = n[2] - n[0];
  double k3 = n[4] - n[0];
  double k4 = n[0] - n[1] - n[2] + n[3];
  double k5 = n[0] - n[2] - n[4] + n[6];
  double k6 = n[0] - n[1] - n[4] + n[5];
  double k7 = -n[0] + n[1] + n[2] - n[3] + n[4] - n[5] - n[6] + n[7];
  double value = k0 + k1 * u + k2 * v + k3 * w + k4 * u * v + k5 * v * w + k6 * w * u + k7 * u * v * w;
  // Gradient: (a) the corner values change with p (d n_i / dp = g_i), weighted by
  // the same trilinear weights; (b) the weights change through the fade.
  glm::dvec3 h0 = g[0];
  glm::dvec3 h1 = g[1] - g[0];
  glm::dvec3 h2 = g[2] - g[0];
  glm::dvec3 h3 = g[4] - g[0];
  glm::dvec3 h4 = g[0] - g[1] - g[2] + g[3];
  glm::dvec3 h5 = g[0] - g[2] - g[4] + g[6];
  glm::dvec3 h6 = g[0] - g[1] - g[4] + g[5];
  glm::dvec3 h7 = -g[0] + g[1] + g[2] - g[3] + g[4] - g[5] - g[6] + g[7];
  glm::dvec3 grad = h0 + h1 * u + h2 * v + h3 * w + h4 * (u * v) + h5 * (v * w) + h6 * (w * u) + h7 * (u * v * w);
  grad.x += du * (k1 + k4 * v + k6 * w + k7 * v * w);
  grad.y += dv * (k2 + k4 * u + k5 * w + k7 * u * w);
  grad.z += dw * (k3 + k6 * u + k5 * v + k7 * u * v);
  return glm::dvec4(value, grad);
}

double turbulence(glm::dvec3 p, int octaves) {
  double sum = 0.0, frequency = 1.0;
  for (int i = 0, n = clampOctaves(octaves); i < n; ++i) {
    sum += std::abs(perlinNoise(p * frequency)) / frequency;
    frequency *= 2.0;
  }
  return sum;
}

double dturbulence(glm::dvec3 p, int octaves) {
  double sum = 0.0, frequency = 1.0;
  glm::dvec3 slope(0.0);
  for (int i = 0, n = clampOctaves(octaves); i < n; ++i) {
    glm::dvec4 ng = perlinNoiseGrad(p * frequency);
    // d/dp [noise(p f) / f] = grad noise(p f): each octave adds its raw gradient.
    slope += glm::dvec3(ng.y, ng.z, ng.w);
    sum += std::abs(ng.x) / frequency / (1.0 + glm::dot(slope, slope));
    frequency *= 2.0;
  }
  return sum;
}
