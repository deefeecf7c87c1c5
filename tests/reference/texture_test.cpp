// Texture kinds: names, defaults and the CPU reference colours (host/reference/texture.cpp).
#include "texture.h"
#include "texture_kinds.h"

#include "mapping.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

// Every kind of the table with a CPU blend formula (all but image).
std::vector<TextureKind> proceduralKinds() {
  std::vector<TextureKind> kinds;
  for (const TextureKindInfo& info : textureKinds())
    if (info.kind != TextureKind::Image) kinds.push_back(info.kind);
  return kinds;
}
const std::vector<TextureKind> kProcedural = proceduralKinds();

TexCoordD coord(glm::dvec2 uv, glm::dvec2 tile, glm::dvec3 solid = glm::dvec3(0.0)) {
  TexCoordD tc;
  tc.uv = uv;
  tc.tile = tile;
  tc.solid = solid;
  return tc;
}

TexCoordD solidCoord(glm::dvec3 solid) { return coord(glm::dvec2(0.0), glm::dvec2(0.0), solid); }

TextureDesc checker(float squares) {
  TextureDesc t = defaultTexture(TextureKind::Checker);
  t.squares = squares;
  return t;
}

// Checker blend at a point of the floor y = 0 with tex_scale s (t = x, b = z).
double floorChecker(float squares, double s, double x, double z) {
  const PlaneFrame f = planeFrame(glm::dvec3(0, 1, 0), 0.0);
  return textureBlendReference(checker(squares), planeTexCoord(f, s, glm::dvec3(x, 0.0, z)));
}

}  // namespace

TEST(TextureChecker, ParityByHand) {
  const TextureDesc t = checker(2.0f);
  // squares 2, tile (0,0): uv (0.25, 0.25) -> cells (0,0), sum 0, even -> color1 (blend 0).
  EXPECT_EQ(textureBlendReference(t, coord({0.25, 0.25}, {0, 0})), 0.0);
  // uv (0.75, 0.25) -> cells (1,0), sum 1 -> color2.
  EXPECT_EQ(textureBlendReference(t, coord({0.75, 0.25}, {0, 0})), 1.0);
  // uv (0.75, 0.75) -> (1,1), sum 2 -> color1.
  EXPECT_EQ(textureBlendReference(t, coord({0.75, 0.75}, {0, 0})), 0.0);
  // tile (-1, 0), uv (0.25, 0.25): 0 + 0 + 2 * (-1 + 0) = -2, even -> color1.
  EXPECT_EQ(textureBlendReference(t, coord({0.25, 0.25}, {-1, 0})), 0.0);
  // tile (-3, 5), uv (0.75, 0.25): 1 + 0 + 2 * 2 = 5, odd -> color2.
  EXPECT_EQ(textureBlendReference(t, coord({0.75, 0.25}, {-3, 5})), 1.0);
  // The colours themselves.
  const glm::dvec3 c1(t.color1), c2(t.color2);
  EXPECT_EQ(textureColorReference(t, coord({0.25, 0.25}, {0, 0})), c1);
  EXPECT_EQ(textureColorReference(t, coord({0.75, 0.25}, {0, 0})), c2);
}

TEST(TextureChecker, NegativeQuadrantThroughThePlaneMapping) {
  // Floor, s = 1, squares 2 (checks of 0.5):
  // x = -0.25: u_p = -0.25 -> tile -1, u 0.75 -> floor(1.5) = 1; z = 0.25 -> 0;
  // sum 1 + 0 + 2 * (-1) = -1, odd -> color2. (Unwrapped: floor(-0.5) + floor(0.5) = -1.)
  // A truncating int(-0.5) = 0 would give even: the classic double-width cell at x = 0.
  EXPECT_EQ(floorChecker(2.0f, 1.0, -0.25, 0.25), 1.0);
  EXPECT_EQ(floorChecker(2.0f, 1.0, 0.25, 0.25), 0.0);
  // x = -0.75: tile -1, u 0.25 -> 0; sum 0 + 0 - 2 = -2, even -> color1.
  EXPECT_EQ(floorChecker(2.0f, 1.0, -0.75, 0.25), 0.0);
  // Both negative: x = -0.25, z = -0.25 -> 1 + 1 + 2 * (-2) = -2, even.
  EXPECT_EQ(floorChecker(2.0f, 1.0, -0.25, -0.25), 0.0);
}

TEST(TextureChecker, OddSquaresAcrossTileBorder) {
  // squares 3, s = 1 (checks of 1/3), z = 0.1 (v cell 0):
  // x = 0.9: tile 0, floor(2.7) = 2 -> even, color1.
  // x = 1.1: tile 1, u 0.1 -> 0, + 3 * 1 = 3 -> odd, color2. Neighbouring checks differ;
  // without the squares * tile term both would be even (2 and 0).
  EXPECT_EQ(floorChecker(3.0f, 1.0, 0.9, 0.1), 0.0);
  EXPECT_EQ(floorChecker(3.0f, 1.0, 1.1, 0.1), 1.0);
  // x = -0.1: tile -1, u 0.9 -> 2, + 3 * (-1) = -1 -> odd; x = 0.1: 0 -> even.
  EXPECT_EQ(floorChecker(3.0f, 1.0, -0.1, 0.1), 1.0);
  EXPECT_EQ(floorChecker(3.0f, 1.0, 0.1, 0.1), 0.0);
  // Same across the v border: z = 0.9 (2) vs z = 1.1 (0 + 3) with x = 0.1.
  EXPECT_EQ(floorChecker(3.0f, 1.0, 0.1, 0.9), 0.0);
  EXPECT_EQ(floorChecker(3.0f, 1.0, 0.1, 1.1), 1.0);
}

TEST(TextureChecker, MatchesUnwrappedCheckerEverywhere) {
  // For whole `squares` the tiled checker equals the parity of floor(x sq / s) + floor(z sq / s).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> d(-50.0, 50.0);
  for (float squares : {1.0f, 2.0f, 3.0f, 5.0f, 8.0f}) {
    for (int i = 0; i < 2000; ++i) {
      const double x = d(rng), z = d(rng), s = 2.5;
      const double cells = std::floor(x * squares / s) + std::floor(z * squares / s);
      const double expected = std::fmod(std::abs(cells), 2.0);
      ASSERT_EQ(floorChecker(squares, s, x, z), expected) << squares << " " << x << " " << z;
    }
  }
}

TEST(TextureChecker, SquaresRoundedToWholeNumberAtLeastOne) {
  // 2.6 -> 3: uv (0.5, 0.1) -> floor(1.5) = 1 -> odd. With 2.6 unrounded: floor(1.3) = 1 too,
  // so use uv (0.7, 0.1): rounded 3 -> floor(2.1) = 2 (even); unrounded floor(1.82) = 1.
  EXPECT_EQ(textureBlendReference(checker(2.6f), coord({0.7, 0.1}, {0, 0})), 0.0);
  // 0.2 -> 1: a whole tile is one check; tile (1, 0) -> odd.
  EXPECT_EQ(textureBlendReference(checker(0.2f), coord({0.7, 0.1}, {1, 0})), 1.0);
}

TEST(TextureSolidChecker, ParityByHand) {
  TextureDesc t = defaultTexture(TextureKind::SolidChecker);
  t.squares = 4.0f;
  // floor(4 * (0.1, 0.1, 0.1)) = (0,0,0): even -> color1.
  EXPECT_EQ(textureBlendReference(t, solidCoord({0.1, 0.1, 0.1})), 0.0);
  // (0.3, 0.1, 0.1) -> (1,0,0): odd -> color2.
  EXPECT_EQ(textureBlendReference(t, solidCoord({0.3, 0.1, 0.1})), 1.0);
  // (0.3, 0.3, 0.3) -> (1,1,1): odd.
  EXPECT_EQ(textureBlendReference(t, solidCoord({0.3, 0.3, 0.3})), 1.0);
  // (-0.1, 0.1, 0.1) -> floor(-0.4) = -1: odd (int truncation would say 0, even).
  EXPECT_EQ(textureBlendReference(t, solidCoord({-0.1, 0.1, 0.1})), 1.0);
  // (-0.3, -0.3, 0.1) -> (-2, -2, 0): even.
  EXPECT_EQ(textureBlendReference(t, solidCoord({-0.3, -0.3, 0.1})), 0.0);
  // On a sphere: n = (1,0,0) -> solid (1, 0.5, 0.5) -> (4, 2, 2): even.
  EXPECT_EQ(textureBlendReference(t, sphereTexCoord(glm::dvec3(1, 0, 0))), 0.0);
  EXPECT_EQ(textureColorReference(t, solidCoord({0.3, 0.1, 0.1})), glm::dvec3(t.color2));
}

TEST(TextureBricks, RunningBondByHand) {
  TextureDesc t = defaultTexture(TextureKind::Bricks);  // 4 columns, 8 rows a tile, mortar 0.1
  ASSERT_EQ(t.columns, 4);
  // Row 0 (even): u = 0.1 is 0.4 of a brick, v = 1/16 mid-row: brick.
  EXPECT_EQ(textureBlendReference(t, coord({0.1, 0.0625}, {0, 0})), 0.0);
  // A row edge (v = 1/8: row 1 starts) and a brick edge of an even row (u = 1/4): mortar.
  EXPECT_EQ(textureBlendReference(t, coord({0.1, 0.125}, {0, 0})), 1.0);
  EXPECT_EQ(textureBlendReference(t, coord({0.25, 0.0625}, {0, 0})), 1.0);
  // Within the joint's half widths (mortar/2 of a row, mortar/4 of a brick), and just outside.
  EXPECT_EQ(textureBlendReference(t, coord({0.1, 0.125 + 0.049 / 8}, {0, 0})), 1.0);
  EXPECT_EQ(textureBlendReference(t, coord({0.1, 0.125 + 0.051 / 8}, {0, 0})), 0.0);
  EXPECT_EQ(textureBlendReference(t, coord({0.25 + 0.024 / 4, 0.0625}, {0, 0})), 1.0);
  EXPECT_EQ(textureBlendReference(t, coord({0.25 + 0.026 / 4, 0.0625}, {0, 0})), 0.0);
  // Row 1 (odd) is shifted half a brick towards +u: its edges lie at u = 1/8 + k/4.
  EXPECT_EQ(textureBlendReference(t, coord({0.25, 0.1875}, {0, 0})), 0.0);
  EXPECT_EQ(textureBlendReference(t, coord({0.125, 0.1875}, {0, 0})), 1.0);
  // Whole tiles, negative ones too, add whole bricks and an even number of rows.
  for (glm::dvec2 tile : {glm::dvec2(1, 0), glm::dvec2(0, 1), glm::dvec2(-3, -5)})
    for (glm::dvec2 uv : {glm::dvec2(0.125, 0.1875), glm::dvec2(0.25, 0.1875), glm::dvec2(0.1, 0.0625)})
      EXPECT_EQ(textureBlendReference(t, coord(uv, tile)), textureBlendReference(t, coord(uv, {0, 0})));
  // No mortar: bricks everywhere, even on their edges.
  t.mortar = 0.0f;
  EXPECT_EQ(textureBlendReference(t, coord({0.25, 0.125}, {0, 0})), 0.0);
}

TEST(TextureNoise, MidColourAtLatticePoints) {
  // solid * scale on the integer lattice -> noise 0 -> t = 0.5.
  TextureDesc t = defaultTexture(TextureKind::Noise);
  t.scale = 4.0f;
  EXPECT_EQ(textureBlendReference(t, solidCoord({0.25, -0.5, 1.0})), 0.5);
  const glm::dvec3 mid = (glm::dvec3(t.color1) + glm::dvec3(t.color2)) * 0.5;
  const glm::dvec3 c = textureColorReference(t, solidCoord({0.25, -0.5, 1.0}));
  EXPECT_NEAR(c.x, mid.x, 1e-15);
  EXPECT_NEAR(c.y, mid.y, 1e-15);
  EXPECT_NEAR(c.z, mid.z, 1e-15);
}

TEST(TextureProcedural, FiniteAndWithinTheColoursForManySamples) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> d(-3.0, 3.0), unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  const PlaneFrame floor = planeFrame(glm::dvec3(0, 1, 0), -2.0);
  for (TextureKind kind : kProcedural) {
    for (int variant = 0; variant < 3; ++variant) {
      TextureDesc t = defaultTexture(kind);
      if (variant == 1) {  // harsher parameters
        t.scale *= 3.0f;
        t.strength *= 4.0f;
        t.octaves = 12;
        t.squares = 5.0f;
      } else if (variant == 2) {  // colours swapped and per-channel mixed
        t.color1 = glm::vec3(0.0f, 1.0f, 0.3f);
        t.color2 = glm::vec3(1.0f, 0.0f, 0.3f);
      }
      double minT = 1.0, maxT = 0.0;
      for (int i = 0; i < 3000; ++i) {
        TexCoordD tc;
        if (i % 3 == 0) {
          tc = sphereTexCoord(glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng))));
        } else if (i % 3 == 1) {
          tc = planeTexCoord(floor, 5.0, glm::dvec3(20.0 * d(rng), -2.0, 20.0 * d(rng)));
        } else {
          tc = coord({unit(rng), unit(rng)}, {std::floor(d(rng)), std::floor(d(rng))},
                     {d(rng), d(rng), d(rng)});
        }
        const double blend = textureBlendReference(t, tc);
        ASSERT_TRUE(blend >= 0.0 && blend <= 1.0) << textureKindName(kind) << " t = " << blend;
        minT = std::min(minT, blend);
        maxT = std::max(maxT, blend);
        const glm::dvec3 c = textureColorReference(t, tc);
        for (int ch = 0; ch < 3; ++ch) {
          const double lo = std::min(t.color1[ch], t.color2[ch]), hi = std::max(t.color1[ch], t.color2[ch]);
          ASSERT_TRUE(std::isfinite(c[ch])) << textureKindName(kind);
          ASSERT_GE(c[ch], lo - 1e-12) << textureKindName(kind);
          ASSERT_LE(c[ch], hi + 1e-12) << textureKindName(kind);
        }
      }
      // Every kind actually varies (uses more than a sliver of the colour range).
      EXPECT_GT(maxT - minT, 0.5) << textureKindName(kind) << " variant " << variant;
    }
  }
}

TEST(TextureProcedural, NoReferenceForImageOrNone) {
  const TexCoordD tc = solidCoord({0.1, 0.2, 0.3});
  EXPECT_THROW(textureColorReference(defaultTexture(TextureKind::Image), tc), std::invalid_argument);
  EXPECT_THROW(textureColorReference(defaultTexture(TextureKind::None), tc), std::invalid_argument);
}

// Every default a kind's number keys start from lies in the range the parser accepts for that
// key (the key rows' ranges, not the defaults): a scene may write any default out and parse.
TEST(TextureProcedural, DefaultsAreSane) {
  for (TextureKind kind : kProcedural) {
    const TextureDesc t = defaultTexture(kind);
    EXPECT_EQ(t.kind, kind);
    const TextureKindInfo& info = textureKindInfo(kind);
    int numbers = 0;
    for (const TextureKey& key : info.keys) {
      if (!key.number && !key.whole) continue;
      const double value = key.number ? double(t.*key.number) : double(t.*key.whole);
      ++numbers;
      EXPECT_TRUE(inRange(key.range, value))
          << info.name << "." << key.name << " defaults to " << value << ", outside " << describeRange(key.range);
    }
    EXPECT_GT(numbers, 0) << info.name;
  }
}
