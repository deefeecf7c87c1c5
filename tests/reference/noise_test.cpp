// Improved Perlin noise, its analytic gradient and the turbulence sums (host/reference/noise.cpp).
#include "noise.h"
#include "noise_permutation.h"

#include "common.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

std::vector<glm::dvec3> randomPoints(int count, double lo, double hi, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<glm::dvec3> points;
  for (int i = 0; i < count; ++i) points.push_back({d(rng), d(rng), d(rng)});
  return points;
}

}  // namespace

TEST(NoisePermutation, IsAPermutationOf0To255RepeatedTwice) {
  const std::array<uint32_t, 512>& p = noisePermutation();
  std::vector<int> seen(256, 0);
  for (int i = 0; i < 256; ++i) {
    ASSERT_LT(p[i], 256u);
    ++seen[p[i]];
    EXPECT_EQ(p[i + 256], p[i]);
  }
  for (int v = 0; v < 256; ++v) EXPECT_EQ(seen[v], 1) << v;
  int fixedPoints = 0;
  for (int i = 0; i < 256; ++i) fixedPoints += p[i] == uint32_t(i);
  EXPECT_LT(fixedPoints, 10);  // shuffled, not the identity
}

TEST(NoisePermutation, IsDeterministic) {
  // Fixed seed + splitmix64 + Fisher-Yates: these values must never change (GPU
  // goldens depend on them). Changing kNoiseSeed or the shuffle changes every image.
  const std::array<uint32_t, 512>& p = noisePermutation();
  const uint32_t first[8] = {180, 125, 203, 221, 61, 132, 192, 73};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(p[i], first[i]) << i;
  EXPECT_EQ(p[255], 237u);
}

TEST(NoisePermutation, FillNoiseTablePacksNeighbourPairsFourPerVector) {
  gpu::NoiseTable table{};
  fillNoiseTable(&table);
  const std::array<uint32_t, 512>& p = noisePermutation();
  for (int i = 0; i < NOISE_PERM_SIZE; ++i) {
    const uint32_t pair = table.pairs[i >> 2][i & 3];
    EXPECT_EQ(pair & 0xFFFFu, p[i]) << i;
    EXPECT_EQ(pair >> 16, p[(i + 1) % 512]) << i;  // the repeat: p[512] is p[0]
  }
  EXPECT_EQ(table.pairs[127][3] >> 16, p[0]);
}

TEST(NoiseValue, Pinned) {
  const glm::dvec3 p(-1.25, 3.7, 100.3);
  EXPECT_NEAR(perlinNoise(p), 0.25952071102453111, 1e-15);
  // At a cell centre every corner value is +-0.5 +- 0.5 (or 0), weights 1/8 each.
  EXPECT_NEAR(perlinNoise(glm::dvec3(0.5)), -0.125, 1e-15);
}

TEST(NoiseValue, ZeroAtLatticePoints) {
  for (int x = -300; x <= 300; x += 37)
    for (int y = -5; y <= 5; ++y)
      for (int z : {-257, -256, -1, 0, 1, 255, 256, 1000}) {
        EXPECT_EQ(perlinNoise(glm::dvec3(x, y, z)), 0.0) << x << " " << y << " " << z;
        EXPECT_EQ(perlinNoiseGrad(glm::dvec3(x, y, z)).x, 0.0);
      }
}

TEST(NoiseValue, RangeAndSpread) {
  double maxAbs = 0.0, sum = 0.0, sumSq = 0.0;
  const auto points = randomPoints(200000, -300.0, 300.0, 1);
  for (glm::dvec3 p : points) {
    double n = perlinNoise(p);
    ASSERT_TRUE(std::isfinite(n));
    maxAbs = std::max(maxAbs, std::abs(n));
    sum += n;
    sumSq += n * n;
  }
  const double mean = sum / points.size(), stddev = std::sqrt(sumSq / points.size() - mean * mean);
  EXPECT_LE(maxAbs, 1.05);
  EXPECT_GT(maxAbs, 0.7);       // not all ~0
  EXPECT_GT(stddev, 0.15);      // measured ~0.27
  EXPECT_LT(std::abs(mean), 0.01);
}

TEST(NoiseValue, PeriodIs256) {
  for (glm::dvec3 p : randomPoints(1000, -50.0, 50.0, 2)) {
    const double n = perlinNoise(p);
    EXPECT_NEAR(perlinNoise(p + glm::dvec3(256, 0, 0)), n, 1e-12);
    EXPECT_NEAR(perlinNoise(p + glm::dvec3(0, -512, 0)), n, 1e-12);
    EXPECT_NEAR(perlinNoise(p + glm::dvec3(0, 0, 256.0 * 4096)), n, 1e-9);
  }
}

TEST(NoiseValue, ContinuousAcrossCellFaces) {
  // Put one coordinate exactly on a lattice plane (including negative ones, where an
  // int() truncation would use the wrong cell) and step 1e-7 either side. The
  // gradient is below ~3, so the two sides differ by < 1e-6.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> d(-20.0, 20.0);
  std::uniform_int_distribution<int> face(-20, 20);
  for (int i = 0; i < 3000; ++i) {
    glm::dvec3 p(d(rng), d(rng), d(rng));
    const int axis = i % 3;
    p[axis] = face(rng);
    glm::dvec3 lo = p, hi = p;
    lo[axis] -= 1e-7;
    hi[axis] += 1e-7;
    ASSERT_NEAR(perlinNoise(lo), perlinNoise(hi), 1e-6) << "axis " << axis << " at " << p[axis];
    ASSERT_NEAR(perlinNoise(lo), perlinNoise(p), 1e-6);
  }
}

TEST(NoiseGradient, ValueMatchesPerlinNoise) {
  for (glm::dvec3 p : randomPoints(2000, -100.0, 100.0, 4))
    EXPECT_NEAR(perlinNoiseGrad(p).x, perlinNoise(p), 1e-14);
}

TEST(NoiseGradient, MatchesCentralDifferences) {
  // Central difference in double with h = 1e-5: truncation ~h^2 * f''' ~ 1e-8,
  // rounding ~1e-16 / 1e-5 = 1e-11. Tolerance: relative 1e-5 (absolute near 0).
  const double h = 1e-5;
  auto points = randomPoints(5000, -300.0, 300.0, 5);
  auto near = randomPoints(1000, -2.0, 2.0, 6);  // cells around 0, incl. negative ones
  points.insert(points.end(), near.begin(), near.end());
  double worst = 0.0;
  for (glm::dvec3 p : points) {
    const glm::dvec4 ng = perlinNoiseGrad(p);
    const glm::dvec3 g(ng.y, ng.z, ng.w);
    glm::dvec3 fd;
    for (int a = 0; a < 3; ++a) {
      glm::dvec3 e(0.0);
      e[a] = h;
      fd[a] = (perlinNoise(p + e) - perlinNoise(p - e)) / (2.0 * h);
    }
    const double err = glm::length(g - fd) / std::max(1.0, glm::length(g));
    worst = std::max(worst, err);
    ASSERT_LE(err, 1e-5) << "p = (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(NoiseGradient, AtLatticePointsIsTheCornerGradient) {
  // At an integer point only that corner counts: noise = g . (p - corner) nearby,
  // so the gradient is exactly g (one of the 12 cube-edge vectors: length sqrt 2).
  for (glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(-3, 7, -11), glm::dvec3(255, 256, -256)}) {
    const glm::dvec4 ng = perlinNoiseGrad(p);
    EXPECT_NEAR(glm::length(glm::dvec3(ng.y, ng.z, ng.w)), std::sqrt(2.0), 1e-15);
  }
}

TEST(NoiseTurbulence, SaneRangeAndFinite) {
  for (glm::dvec3 p : randomPoints(5000, -100.0, 100.0, 7)) {
    for (int octaves : {1, 2, 4, 6, 8}) {
      const double t = turbulence(p, octaves), dt = dturbulence(p, octaves);
      ASSERT_TRUE(std::isfinite(t) && std::isfinite(dt));
      ASSERT_GE(t, 0.0);
      ASSERT_LT(t, 2.1);  // sum of 1.05 / 2^i
      ASSERT_GE(dt, 0.0);
      ASSERT_LE(dt, t + 1e-15);  // damping only removes
    }
  }
}

TEST(NoiseTurbulence, DefinitionForFewOctaves) {
  for (glm::dvec3 p : randomPoints(500, -50.0, 50.0, 8)) {
    const double n0 = perlinNoise(p), n1 = perlinNoise(2.0 * p), n2 = perlinNoise(4.0 * p);
    EXPECT_EQ(turbulence(p, 0), 0.0);
    EXPECT_NEAR(turbulence(p, 1), std::abs(n0), 1e-15);
    EXPECT_NEAR(turbulence(p, 3), std::abs(n0) + std::abs(n1) / 2 + std::abs(n2) / 4, 1e-14);
    // dturbulence: octave i divided by 1 + |sum of the raw gradients of octaves 0..i|^2.
    const glm::dvec4 g0 = perlinNoiseGrad(p), g1 = perlinNoiseGrad(2.0 * p);
    const glm::dvec3 s0(g0.y, g0.z, g0.w), s1 = s0 + glm::dvec3(g1.y, g1.z, g1.w);
    const double expected = std::abs(n0) / (1.0 + glm::dot(s0, s0)) + std::abs(n1) / 2.0 / (1.0 + glm::dot(s1, s1));
    EXPECT_NEAR(dturbulence(p, 2), expected, 1e-14);
    EXPECT_EQ(dturbulence(p, 0), 0.0);
    EXPECT_EQ(turbulence(p, -3), 0.0);
  }
}

TEST(NoiseTurbulence, OctavesClampedAtMaximum) {
  const glm::dvec3 p(1.3, -2.7, 0.45);
  EXPECT_EQ(turbulence(p, 1000), turbulence(p, kNoiseMaxOctaves));
  EXPECT_EQ(dturbulence(p, 1000), dturbulence(p, kNoiseMaxOctaves));
}

TEST(NoiseTurbulence, NotDegenerate) {
  // Typical values (measured: turbulence mean ~0.44 at 6 octaves, dturbulence ~0.17).
  double t = 0.0, dt = 0.0;
  const auto points = randomPoints(20000, -100.0, 100.0, 9);
  for (glm::dvec3 p : points) {
    t += turbulence(p, 6);
    dt += dturbulence(p, 6);
  }
  t /= points.size();
  dt /= points.size();
  EXPECT_GT(t, 0.3);
  EXPECT_LT(t, 0.6);
  EXPECT_GT(dt, 0.1);
  EXPECT_LT(dt, t);
}
