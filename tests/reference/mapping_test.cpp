// Texture coordinates (host/reference/mapping.cpp) against hand-computed values.
#include "mapping.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

constexpr double kEps = 1e-12;

void expectVecNear(glm::dvec3 a, glm::dvec3 b, double eps, const char* what) {
  EXPECT_NEAR(a.x, b.x, eps) << what;
  EXPECT_NEAR(a.y, b.y, eps) << what;
  EXPECT_NEAR(a.z, b.z, eps) << what;
}

bool finite3(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The course's floor: plane { normal = (0,1,0); distance = -2.0; tex_scale = 5.0; }
PlaneFrame courseFloor() { return planeFrame(glm::dvec3(0, 1, 0), -2.0); }

}  // namespace

// ---------------------------------------------------------------------------
// Plane basis rule
// ---------------------------------------------------------------------------

TEST(MappingPlaneFrame, FloorIsXThenZ) {
  // n = (0,1,0): n_x^2 = 0 <= 1/2, so the helper is +x; x - (x.n) n = x; b = x X y = z.
  PlaneFrame f = courseFloor();
  EXPECT_EQ(f.normal, glm::dvec3(0, 1, 0));
  EXPECT_EQ(f.tangent, glm::dvec3(1, 0, 0));
  EXPECT_EQ(f.binormal, glm::dvec3(0, 0, 1));
  EXPECT_EQ(f.distance, -2.0);
}

TEST(MappingPlaneFrame, AxisNormalsFollowTheDocumentedRule) {
  struct Case {
    glm::dvec3 n, t, b;
  };
  const Case cases[] = {
      {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},  // helper x; x X (-y) = -z
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   // helper x; x X z = -y
      {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},   // helper x; x X (-z) = y
      {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    // n_x^2 = 1 > 1/2: helper z; z X x = y
      {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},  // helper z; z X (-x) = -y
  };
  for (const Case& c : cases) {
    PlaneFrame f = planeFrame(c.n, 0.0);
    expectVecNear(f.tangent, c.t, kEps, "tangent");
    expectVecNear(f.binormal, c.b, kEps, "binormal");
  }
}

TEST(MappingPlaneFrame, NormalisesNormalAndDistanceTogether) {
  // (0,2,0).x = -4 is the plane y = -2.
  PlaneFrame f = planeFrame(glm::dvec3(0, 2, 0), -4.0);
  EXPECT_EQ(f.normal, glm::dvec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(f.distance, -2.0);
}

TEST(MappingPlaneFrame, RejectsDegenerateNormals) {
  EXPECT_THROW(planeFrame(glm::dvec3(0, 0, 0), 1.0), std::invalid_argument);
  EXPECT_THROW(planeFrame(glm::dvec3(NAN, 1, 0), 1.0), std::invalid_argument);
  EXPECT_THROW(planeFrame(glm::dvec3(0, INFINITY, 0), 1.0), std::invalid_argument);
}

TEST(MappingPlaneFrame, OrthonormalRightHandedAndFiniteForManyNormals) {
  std::vector<glm::dvec3> normals = {
      {1, 0, 0},  {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
      // near-parallel to the axes (where cross(n, up) style bases break down)
      {1, 1e-9, 0}, {-1, 0, 1e-12}, {1e-12, 1, 1e-12}, {-1e-15, -1, 0}, {0, 1e-300, 1},
      // either side of the helper switch n_x^2 = 1/2
      {1, 1, 0}, {1, 1 + 1e-12, 0}, {1, 1 - 1e-12, 0}, {-1, 0, 1}, {1, 1, 1},
      // tiny and huge lengths
      {1e-200, 3e-200, -2e-200}, {1e200, -1e200, 5e199},
  };
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 2000; ++i) normals.push_back({gauss(rng), gauss(rng), gauss(rng)});

  for (glm::dvec3 n0 : normals) {
    PlaneFrame f = planeFrame(n0, 1.0);
    SCOPED_TRACE(::testing::Message() << "n = (" << n0.x << ", " << n0.y << ", " << n0.z << ")");
    ASSERT_TRUE(finite3(f.tangent) && finite3(f.binormal) && finite3(f.normal));
    EXPECT_NEAR(glm::length(f.normal), 1.0, kEps);
    EXPECT_NEAR(glm::length(f.tangent), 1.0, kEps);
    EXPECT_NEAR(glm::length(f.binormal), 1.0, kEps);
    EXPECT_NEAR(glm::dot(f.tangent, f.normal), 0.0, kEps);
    EXPECT_NEAR(glm::dot(f.binormal, f.normal), 0.0, kEps);
    EXPECT_NEAR(glm::dot(f.tangent, f.binormal), 0.0, kEps);
    // b = t x n, i.e. (t, n, b) is right-handed like (x, y, z).
    expectVecNear(glm::cross(f.tangent, f.normal), f.binormal, kEps, "b = t x n");
    // The normal keeps its direction.
    EXPECT_GT(glm::dot(f.normal, n0), 0.0);
  }
}

// ---------------------------------------------------------------------------
// Plane texture coordinates, eqs (6), (1), (2)
// ---------------------------------------------------------------------------

TEST(MappingPlane, NotesNegativeExample) {
  // Floor y = -2, s = 5, t = x, b = z, o' = d n = (0,-2,0).
  // p = (-13.909, -2, 7.5): u_p = -13.909, u_p/s = -2.7818, floor = -3 (an int cast
  // would give -2), u = -2.7818 - (-3) = 0.2182.  v_p = 7.5, v_p/s = 1.5 -> tile 1, v = 0.5.
  TexCoordD tc = planeTexCoord(courseFloor(), 5.0, glm::dvec3(-13.909, -2.0, 7.5));
  EXPECT_NEAR(tc.uv.x, 0.2182, 1e-12);
  EXPECT_NEAR(tc.uv.y, 0.5, 1e-12);
  EXPECT_EQ(tc.tile.x, -3.0);
  EXPECT_EQ(tc.tile.y, 1.0);
  // solid = p / s = (-2.7818, -0.4, 1.5)
  expectVecNear(tc.solid, glm::dvec3(-2.7818, -0.4, 1.5), 1e-12, "solid");
}

TEST(MappingPlane, SmallNegativeCoordinates) {
  // p = (-0.5, -2, -4.5), s = 5: u_p/s = -0.1 -> tile -1, u = 0.9; v_p/s = -0.9 -> tile -1, v = 0.1.
  TexCoordD tc = planeTexCoord(courseFloor(), 5.0, glm::dvec3(-0.5, -2.0, -4.5));
  EXPECT_NEAR(tc.uv.x, 0.9, 1e-12);
  EXPECT_NEAR(tc.uv.y, 0.1, 1e-12);
  EXPECT_EQ(tc.tile, glm::dvec2(-1.0, -1.0));
}

TEST(MappingPlane, PointsExactlyOnTileBorders) {
  const PlaneFrame f = courseFloor();
  // p = (10, -2, -5): u_p/s = 10/5 = 2 exactly -> tile 2, u = 0; v_p/s = -1 -> tile -1, v = 0.
  TexCoordD a = planeTexCoord(f, 5.0, glm::dvec3(10.0, -2.0, -5.0));
  EXPECT_EQ(a.uv, glm::dvec2(0.0, 0.0));
  EXPECT_EQ(a.tile, glm::dvec2(2.0, -1.0));
  // p = (-5, -2, 0): u_p/s = -1 -> tile -1, u = 0 (not 1); v_p/s = 0 -> tile 0, v = 0.
  TexCoordD b = planeTexCoord(f, 5.0, glm::dvec3(-5.0, -2.0, 0.0));
  EXPECT_EQ(b.uv, glm::dvec2(0.0, 0.0));
  EXPECT_EQ(b.tile, glm::dvec2(-1.0, 0.0));
  // The origin's projection o' = (0,-2,0) is uv (0,0) of tile (0,0).
  TexCoordD c = planeTexCoord(f, 5.0, glm::dvec3(0.0, -2.0, 0.0));
  EXPECT_EQ(c.uv, glm::dvec2(0.0, 0.0));
  EXPECT_EQ(c.tile, glm::dvec2(0.0, 0.0));
}

TEST(MappingPlane, UvStaysInUnitIntervalAndTilePlusUvIsUnwrapped) {
  const PlaneFrame f = courseFloor();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1000.0, 1000.0);
  for (int i = 0; i < 10000; ++i) {
    glm::dvec3 p(coord(rng), -2.0, coord(rng));
    TexCoordD tc = planeTexCoord(f, 5.0, p);
    ASSERT_GE(tc.uv.x, 0.0);
    ASSERT_LT(tc.uv.x, 1.0);
    ASSERT_GE(tc.uv.y, 0.0);
    ASSERT_LT(tc.uv.y, 1.0);
    ASSERT_NEAR(tc.tile.x + tc.uv.x, p.x / 5.0, 1e-12);
    ASSERT_NEAR(tc.tile.y + tc.uv.y, p.z / 5.0, 1e-12);
  }
}

TEST(MappingPlane, DistanceNonZeroWithTiltedNormal) {
  // normal (0,3,4), distance 10 -> n = (0, 0.6, 0.8), d = 10/5 = 2, o' = (0, 1.2, 1.6).
  // n_x = 0: helper x, t = (1,0,0); b = t x n = (0*0.8 - 0*0.6, 0*0 - 1*0.8, 1*0.6 - 0*0) = (0, -0.8, 0.6).
  PlaneFrame f = planeFrame(glm::dvec3(0, 3, 4), 10.0);
  expectVecNear(f.normal, glm::dvec3(0, 0.6, 0.8), kEps, "n");
  EXPECT_NEAR(f.distance, 2.0, kEps);
  expectVecNear(f.tangent, glm::dvec3(1, 0, 0), kEps, "t");
  expectVecNear(f.binormal, glm::dvec3(0, -0.8, 0.6), kEps, "b");
  // p = o' + 3 t + 4.5 b = (3, 1.2 - 3.6, 1.6 + 2.7) = (3, -2.4, 4.3)
  // (on the plane: -2.4*0.6 + 4.3*0.8 = -1.44 + 3.44 = 2).
  // s = 2: u_p/s = 3/2 = 1.5 -> tile 1, u 0.5; v_p/s = 4.5/2 = 2.25 -> tile 2, v 0.25.
  TexCoordD tc = planeTexCoord(f, 2.0, glm::dvec3(3.0, -2.4, 4.3));
  EXPECT_NEAR(tc.uv.x, 0.5, 1e-12);
  EXPECT_NEAR(tc.uv.y, 0.25, 1e-12);
  EXPECT_EQ(tc.tile, glm::dvec2(1.0, 2.0));
  expectVecNear(tc.solid, glm::dvec3(1.5, -1.2, 2.15), 1e-12, "solid = p / 2");
}

TEST(MappingPlane, ObliqueNormalWithXComponent) {
  // normal (1,2,2), distance 3 -> n = (1,2,2)/3, d = 1, o' = (1,2,2)/3.
  // n_x^2 = 1/9 <= 1/2: helper x; x - (x.n) n = (1,0,0) - (1,2,2)/9 = (8,-2,-2)/9,
  // length 2 sqrt(2)/3, so t = (4,-1,-1)/(3 sqrt 2).
  // b = t x n = ((-1)(2) - (-1)(2), (-1)(1) - (4)(2), (4)(2) - (-1)(1)) / (9 sqrt 2)
  //           = (0, -9, 9) / (9 sqrt 2) = (0, -1, 1)/sqrt 2.
  const double r2 = std::sqrt(2.0);
  PlaneFrame f = planeFrame(glm::dvec3(1, 2, 2), 3.0);
  EXPECT_NEAR(f.distance, 1.0, kEps);
  expectVecNear(f.tangent, glm::dvec3(4, -1, -1) / (3.0 * r2), kEps, "t");
  expectVecNear(f.binormal, glm::dvec3(0, -1, 1) / r2, kEps, "b");
  // p = o' + (3 sqrt 2) t + (-sqrt 2) b = (1,2,2)/3 + (4,-1,-1) + (0,1,-1) = (13/3, 2/3, -4/3).
  // s = 1: u_p = 3 sqrt 2 = 4.2426... -> tile 4, u = 3 sqrt 2 - 4 = 0.242640687;
  //        v_p = -sqrt 2 = -1.41421... -> tile -2, v = 2 - sqrt 2 = 0.585786438.
  TexCoordD tc = planeTexCoord(f, 1.0, glm::dvec3(13.0 / 3.0, 2.0 / 3.0, -4.0 / 3.0));
  EXPECT_NEAR(tc.uv.x, 3.0 * r2 - 4.0, 1e-12);
  EXPECT_NEAR(tc.uv.y, 2.0 - r2, 1e-12);
  EXPECT_EQ(tc.tile, glm::dvec2(4.0, -2.0));
}

TEST(MappingPlane, RejectsNonPositiveScale) {
  EXPECT_THROW(planeTexCoord(courseFloor(), 0.0, glm::dvec3(0)), std::invalid_argument);
  EXPECT_THROW(planeTexCoord(courseFloor(), -1.0, glm::dvec3(0)), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// Sphere texture coordinates, eqs (7), (8), (9)
// ---------------------------------------------------------------------------

TEST(MappingSphere, HandPickedNormals) {
  struct Case {
    glm::dvec3 n;
    double u, v;
  };
  const double h = std::sqrt(0.5), s3 = std::sqrt(3.0) / 2.0;
  const Case cases[] = {
      {{1, 0, 0}, 0.5, 0.5},    // phi = atan2(0, 1) = 0 -> u = pi/2pi; theta = 0 -> v = (pi/2)/pi
      {{0, 0, 1}, 0.75, 0.5},   // phi = pi/2 -> u = (3pi/2)/2pi
      {{0, 0, -1}, 0.25, 0.5},  // phi = -pi/2 -> u = (pi/2)/2pi
      {{-1, 0, 0}, 1.0, 0.5},   // phi = atan2(+0, -1) = +pi -> u = 1 (u = 0 for n_z = -0, below)
      {{h, h, 0}, 0.5, 0.75},   // theta = pi/4 -> v = (3pi/4)/pi
      {{h, -h, 0}, 0.5, 0.25},  // theta = -pi/4
      {{-0.5, 0, -s3}, 1.0 / 6.0, 0.5},  // phi = -2pi/3 -> u = (pi/3)/2pi
      {{0, 1, 0}, 0.5, 1.0},    // north pole: phi := 0 (atan2(0,0) guarded), theta = pi/2
      {{0, -1, 0}, 0.5, 0.0},   // south pole
  };
  for (const Case& c : cases) {
    TexCoordD tc = sphereTexCoord(c.n);
    SCOPED_TRACE(::testing::Message() << "n = (" << c.n.x << ", " << c.n.y << ", " << c.n.z << ")");
    EXPECT_NEAR(tc.uv.x, c.u, 1e-15);
    EXPECT_NEAR(tc.uv.y, c.v, 1e-15);
    EXPECT_EQ(tc.tile, glm::dvec2(0.0));
  }
}

TEST(MappingSphere, MinusXSeamWithNegativeZero) {
  // atan2(-0, -1) = -pi -> u = 0: the other side of the seam (REPEAT makes it the same texel).
  TexCoordD tc = sphereTexCoord(glm::dvec3(-1.0, 0.0, -0.0));
  EXPECT_EQ(tc.uv.x, 0.0);
}

TEST(MappingSphere, PolesAndRoundingPastOneGiveNoNaN) {
  const glm::dvec3 ns[] = {
      {0, 1, 0},  {0, -1, 0}, {-0.0, 1, -0.0}, {0, 1 + 4.4e-16, 0}, {1e-9, 1 + 2.2e-16, 0},
      {0, -1 - 4.4e-16, 0}, {-1e-300, -1, 1e-300},
  };
  for (glm::dvec3 n : ns) {
    TexCoordD tc = sphereTexCoord(n);
    ASSERT_TRUE(std::isfinite(tc.uv.x) && std::isfinite(tc.uv.y)) << n.x << " " << n.y << " " << n.z;
    EXPECT_GE(tc.uv.x, 0.0);
    EXPECT_LE(tc.uv.x, 1.0);
    EXPECT_NEAR(tc.uv.y, n.y > 0 ? 1.0 : 0.0, 1e-7);
  }
  EXPECT_EQ(sphereTexCoord(glm::dvec3(0, 1 + 4.4e-16, 0)).uv.y, 1.0);  // clamped, not NaN
}

TEST(MappingSphere, SolidIsHalfNormalPlusHalf) {
  // (n+1)/2 for n = (0.6, 0, -0.8): (0.8, 0.5, 0.1)
  TexCoordD tc = sphereTexCoord(glm::dvec3(0.6, 0.0, -0.8));
  expectVecNear(tc.solid, glm::dvec3(0.8, 0.5, 0.1), 1e-15, "solid");
  expectVecNear(sphereTexCoord(glm::dvec3(0, -1, 0)).solid, glm::dvec3(0.5, 0.0, 0.5), 0.0, "south pole");
}

TEST(MappingSphere, UvInUnitSquareForRandomNormals) {
  std::mt19937_64 rng(99);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 10000; ++i) {
    glm::dvec3 n = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    TexCoordD tc = sphereTexCoord(n);
    ASSERT_GE(tc.uv.x, 0.0);
    ASSERT_LE(tc.uv.x, 1.0);
    ASSERT_GE(tc.uv.y, 0.0);
    ASSERT_LE(tc.uv.y, 1.0);
    // Inverting (8): the uv gives back the normal.
    const double pi = 3.14159265358979323846;
    double phi = tc.uv.x * 2.0 * pi - pi, theta = tc.uv.y * pi - 0.5 * pi;
    glm::dvec3 back(std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi));
    ASSERT_NEAR(glm::length(back - n), 0.0, 1e-12);
  }
}

// --- texture placement and image orientation (docs/textures.md) ---------------------------

TexturePlacement placement(glm::dvec3 rotate, double scale = 1.0, glm::dvec3 offset = glm::dvec3(0.0)) {
  TexturePlacement p;
  p.rotate = rotate;
  p.scale = scale;
  p.offset = offset;
  return p;
}

TEST(MappingPlacement, RotationIsRzRyRxRightHanded) {
  // A quarter turn about x takes y to z, about y takes z to x, about z takes x to y.
  expectVecNear(placementRotation({90, 0, 0}) * glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1), 1e-15, "x");
  expectVecNear(placementRotation({0, 90, 0}) * glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), 1e-15, "y");
  expectVecNear(placementRotation({0, 0, 90}) * glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), 1e-15, "z");
  // x first, about the fixed axes: (90, 90, 0) takes y to z (x), then z to x (y).
  expectVecNear(placementRotation({90, 90, 0}) * glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), 1e-15, "x then y");
}

TEST(MappingPlacement, HalfTurnAboutTheSphereAxisTurnsTheMap) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int i = 0; i < 100; ++i) {
    glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    TexCoordD turned = sphereTexCoord(placement({0, 180, 0}), n);
    TexCoordD expected = sphereTexCoord(glm::dvec3(-n.x, n.y, -n.z));
    EXPECT_NEAR(std::fmod(turned.uv.x - expected.uv.x + 1.5, 1.0), 0.5, 1e-12);
    EXPECT_NEAR(turned.uv.y, expected.uv.y, 1e-12);
    EXPECT_TRUE(turned.clampV);
  }
}

TEST(MappingPlacement, SphereScaleRepeatsVAndOffsetShiftsLast) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0.8, -0.5));
  const TexCoordD plain = sphereTexCoord(n);
  TexCoordD tc = sphereTexCoord(placement({0, 0, 0}, 0.25, {0.1, 0.2, 0.3}), n);
  glm::dvec2 unwrapped = plain.uv * 4.0 + glm::dvec2(0.1, 0.2);
  expectVecNear(glm::dvec3(tc.tile + tc.uv, 0), glm::dvec3(unwrapped, 0), 1e-12, "uv / s + offset");
  EXPECT_FALSE(tc.clampV);  // v repeats
  expectVecNear(tc.solid, plain.solid * 4.0 + glm::dvec3(0.1, 0.2, 0.3), 1e-12, "solid / s + offset");
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(1.0 - tc.uv.x, 1.0 - tc.uv.y, 0), 0.0, "image");
}

TEST(MappingPlacement, TurnAboutThePlaneNormalTurnsThePatternInThePlane) {
  // The floor y = -2 (t = +x, b = +z), its texture a quarter turn about +y: the point the
  // unturned u axis reached, (1, 0, 0) from the origin, lies at R (1, 0, 0) = (0, 0, -1).
  const PlaneFrame f = courseFloor();
  TexCoordD tc = planeTexCoord(f, placement({0, 90, 0}), glm::dvec3(0, -2, -1));
  expectVecNear(glm::dvec3(tc.tile + tc.uv, 0), glm::dvec3(1, 0, 0), 1e-12, "u axis turned");
  tc = planeTexCoord(f, placement({0, 90, 0}, 2.0, {0.25, 0.5, 0}), glm::dvec3(1, -2, 0));
  expectVecNear(glm::dvec3(tc.tile + tc.uv, 0), glm::dvec3(0.25, 1.0, 0), 1e-12, "v axis turned, / s, + offset");
  expectVecNear(tc.solid, glm::dvec3(0, -2, 1) / 2.0 + glm::dvec3(0.25, 0.5, 0), 1e-12, "solid p' / s + offset");
}

TEST(MappingPlacement, ImagesReadUprightOnPlanes) {
  // The floor seen from above: the image's top towards -z, its left edge at -x; its top-left
  // corner at the origin d n.
  TexCoordD tc = planeTexCoord(courseFloor(), 1.0, glm::dvec3(0.1, -2, 0.2));
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(0.1, 0.2, 0), 1e-12, "floor");
  // A wall facing +z (top +y, right +x) and one facing -x (top +y, right +z).
  tc = planeTexCoord(planeFrame({0, 0, 1}, 0), 1.0, glm::dvec3(0.1, -0.2, 0));
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(0.1, 0.2, 0), 1e-12, "+z wall");
  tc = planeTexCoord(planeFrame({-1, 0, 0}, 0), 1.0, glm::dvec3(0, -0.2, 0.1));
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(0.1, 0.2, 0), 1e-12, "-x wall");
  // The ceiling seen from below: top towards -z, right -x.
  tc = planeTexCoord(planeFrame({0, -1, 0}, 0), 1.0, glm::dvec3(-0.1, 0, 0.2));
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(0.1, 0.2, 0), 1e-12, "ceiling");
  // The oblique (1, 1, 1): the top along +y projected, tiling seamless across the corner.
  const PlaneFrame oblique = planeFrame({1, 1, 1}, 0);
  const glm::dvec3 up = imageUpAxis(oblique.normal), right = glm::cross(up, oblique.normal);
  expectVecNear(up, glm::normalize(glm::dvec3(-1, 2, -1)), 1e-15, "up");
  tc = planeTexCoord(oblique, 1.0, 0.3 * right - 0.4 * up);
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(0.3, 0.4, 0), 1e-12, "oblique");
  tc = planeTexCoord(oblique, 1.0, -0.3 * right + 0.4 * up);
  expectVecNear(glm::dvec3(tc.image, 0), glm::dvec3(0.7, 0.6, 0), 1e-12, "oblique, next tile");
}
