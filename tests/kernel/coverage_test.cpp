// The coverage filter (FILTER_COVERAGE, shaders/coverage.glsl) against the float64 reference's
// box-filtered pixels: silhouettes, the horizon and shadow edges each alone in an untextured
// scene (so that the edge's share of the pixel is all that differs from the reference), then
// the course scene; and every pixel no edge crosses bit-identical to the box filter's.
#include "support/course_scene.h"
#include "support/gpu_fixture.h"
#include "support/reference_rmse.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"
#include "scene_limits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

class CoverageTest : public RenderTest {};

// The largest channel difference of a float image from the reference, and where.
struct WorstPixel {
  double difference = 0.0;
  int x = -1, y = -1;
};
WorstPixel worstPixel(const std::vector<float>& image, const ReferenceImage& ref) {
  WorstPixel worst;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = size_t(y) * ref.width + x;
        const double d = std::abs(double(image[4 * i + c]) - ref.rgb[3 * i + c]);
        if (d > worst.difference) worst = {d, x, y};
      }
  return worst;
}

Scene sceneFrom(const std::string& body) {
  return parseSceneText(body + R"(
camera { eye = (0, 1.2, 6); lookat = (0, 0.8, 0); up = (0, 1, 0); fov = 40; }
background = (0.1, 0.2, 0.6);
)",
                        "coverage.cfg");
}

// A sphere of one colour in front of the background, lit by the ambient term alone.
Scene silhouetteScene() {
  return sceneFrom(R"(
material white { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0); }
ambient_light = (1, 1, 1);
sphere { center = (0.3, 0.9, 0); radius = 1.1; white; }
)");
}

// A floor of one colour to the horizon, lit by the ambient term alone.
Scene horizonScene() {
  return parseSceneText(R"(
material grey { ambient = (0.9, 0.8, 0.2); diffuse = (0, 0, 0); specular = (0, 0, 0); }
ambient_light = (1, 1, 1);
background = (0.1, 0.2, 0.6);
camera { eye = (0, 1, 0); lookat = (0, 0.93, -1); up = (0, 1, 0); fov = 50; }
plane { normal = (0, 1, 0); distance = 0; grey; }
)",
                        "horizon.cfg");
}

// A sphere's shadow on a diffuse floor, with the sphere out of view: only the shadow's edge.
Scene shadowScene() {
  return parseSceneText(R"(
material floor { ambient = (0.1, 0.1, 0.1); diffuse = (0.8, 0.8, 0.8); specular = (0, 0, 0); }
material ball { ambient = (0, 0, 0); diffuse = (1, 1, 1); specular = (0, 0, 0); }
ambient_light = (1, 1, 1);
background = (0, 0, 0);
light { position = (0, 6, 0); color = (1, 1, 1); }
camera { eye = (0, 4, 3); lookat = (0, 0, 0); up = (0, 1, 0); fov = 40; }
plane { normal = (0, 1, 0); distance = 0; floor; }
sphere { center = (0.4, 3, 0.2); radius = 0.6; ball; }
)",
                        "shadow.cfg");
}

// A floor meeting a wall, each of one colour, lit by the ambient term alone: only the crease.
Scene creaseScene() {
  return parseSceneText(R"(
material floor { ambient = (0.9, 0.8, 0.2); diffuse = (0, 0, 0); specular = (0, 0, 0); }
material wall { ambient = (0.1, 0.3, 0.9); diffuse = (0, 0, 0); specular = (0, 0, 0); }
ambient_light = (1, 1, 1);
background = (0, 0, 0);
camera { eye = (0.7, 1.5, 4); lookat = (0, 0.4, 0); up = (0, 1, 0); fov = 50; }
plane { normal = (0, 1, 0); distance = 0; floor; }
plane { normal = (0.3, 0, 1); distance = -1; wall; }
)",
                        "crease.cfg");
}

constexpr uint32_t kWidth = 96, kHeight = 72;
// Samples per side of the reference: its box-filtered pixels within about 1/(2 * 48) of the
// exact share of a straight edge.
constexpr int kReferenceSide = 48;

}  // namespace

// Each edge alone: a pixel's value is the mix of the two sides by the edge's share of the pixel,
// which the coverage filter computes in closed form and the box filter rounds to 0 or 1 (to
// quarters at 2 x 2 samples, where the coverage filter takes each sample's cell). The bound: the
// reference's own error (a share quantised to 1/48^2 of a pixel along each row of samples, up to
// 1/48 of the step) plus the curvature of a silhouette across a pixel, measured at 0.004
// (silhouette), 0.007 (horizon), 0.006 (shadow) and 0.001 (crease) at 1 spp on lavapipe and at
// 0.003, 0.007, 0.003 and 0.001 at 4; the box filter's worst pixel is 0.32-0.45 at 1 spp, near
// half the step in each, and 0.08-0.20 at 4.
TEST_F(CoverageTest, EachEdgeAloneMatchesTheReferencePixelByPixel) {
  struct Case {
    const char* name;
    Scene scene;
  } cases[] = {{"silhouette", silhouetteScene()},
               {"horizon", horizonScene()},
               {"shadow", shadowScene()},
               {"crease", creaseScene()}};
  for (Case& c : cases) {
    SCOPED_TRACE(c.name);
    const ReferenceImage ref = renderReference(c.scene, kWidth, kHeight, kReferenceSide);
    for (uint32_t side : {1u, 2u}) {
      SCOPED_TRACE(std::to_string(side * side) + " spp");
      const WorstPixel box = worstPixel(render(c.scene, kWidth, kHeight, OUTPUT_SHADED, side, FILTER_BOX), ref);
      const WorstPixel coverage =
          worstPixel(render(c.scene, kWidth, kHeight, OUTPUT_SHADED, side, FILTER_COVERAGE), ref);
      EXPECT_GT(box.difference, side == 1 ? 0.2 : 0.05) << "the scene shows no hard edge to cover";
      EXPECT_LT(coverage.difference, 0.03) << "at pixel (" << coverage.x << ", " << coverage.y << ")";
    }
  }
}

// The course scene with two materials on the sphere: the coverage filter's RMSE against the
// reference is well below the box filter's, at 1 and 4 spp (measured: 0.37-0.56 of it).
TEST_F(CoverageTest, CourseSceneIsCloserToTheReferenceThanTheBoxFilter) {
  for (const char* material : {"aSolidChecker", "aMarble"}) {
    SCOPED_TRACE(material);
    const Scene scene = courseScene(material);
    const ReferenceImage ref = renderReference(scene, kWidth, kHeight, 32);
    for (uint32_t side : {1u, 2u}) {
      SCOPED_TRACE(std::to_string(side * side) + " spp");
      const double box =
          rmseAgainstReference(render(scene, kWidth, kHeight, OUTPUT_SHADED, side, FILTER_BOX).data(), ref);
      const double coverage =
          rmseAgainstReference(render(scene, kWidth, kHeight, OUTPUT_SHADED, side, FILTER_COVERAGE).data(), ref);
      EXPECT_LT(coverage, 0.75 * box) << "box " << box << ", coverage " << coverage;
    }
  }
}

// What the centre of each pixel sees, in float64: the object hit and the lights its shadow rays
// find blocked.
std::vector<long long> centreStates(const Scene& scene, uint32_t width, uint32_t height) {
  const ReferenceCamera camera = referenceCamera(scene.camera, int(width), int(height));
  std::vector<long long> states(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const glm::dvec3 d = referenceRayDirection(camera, int(x), int(y));
      const ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, d, false);
      long long state = hit.kind * 1000 + hit.index;
      const glm::dvec3 n = glm::dot(hit.n, d) > 0.0 ? -hit.n : hit.n;
      for (size_t l = 0; hit.kind != 0 && l < scene.lights.size(); ++l) {
        const glm::dvec3 toLight = scene.lights[l].position - hit.p;
        const double distance = glm::length(toLight);
        if (glm::dot(n, toLight) <= 0.0) continue;
        const glm::dvec3 origin = hit.p + n * (1e-9 * (1.0 + glm::length(hit.p)));
        const ReferenceHit blocker = referenceClosestHit(scene, origin, toLight / distance, false);
        if (blocker.kind != 0 && blocker.t < distance) state += 1LL << (20 + l);
      }
      states[size_t(y) * width + x] = state;
    }
  return states;
}

// Where no edge crosses a pixel the coverage filter leaves the box filter's value, at 1 spp and,
// where its samples go one dispatch each, at 4 (the progressive sums are bit-identical to the box
// kernel's N x N loop): every pixel that differs lies next to a change of what the centres see
// (an object, or a light blocked), within two pixels (float against float64 can list a pixel
// next to a grazing centre).
TEST_F(CoverageTest, PixelsNoEdgeCrossesAreBitIdenticalToTheBoxFilter) {
  const Scene scene = courseScene("aSolidChecker");
  const std::vector<long long> states = centreStates(scene, kWidth, kHeight);
  for (uint32_t side : {1u, 2u}) {
    SCOPED_TRACE(std::to_string(side * side) + " spp");
    const std::vector<float> box = render(scene, kWidth, kHeight, OUTPUT_SHADED, side, FILTER_BOX);
    const std::vector<float> coverage = render(scene, kWidth, kHeight, OUTPUT_SHADED, side, FILTER_COVERAGE);
    size_t differing = 0, unexplained = 0;
    for (int y = 0; y < int(kHeight); ++y)
      for (int x = 0; x < int(kWidth); ++x) {
        const size_t i = size_t(y) * kWidth + x;
        if (std::equal(&box[4 * i], &box[4 * i + 4], &coverage[4 * i])) continue;
        ++differing;
        bool edge = false;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < int(kWidth) && ny < int(kHeight))
              edge |= states[size_t(ny) * kWidth + nx] != states[i];
          }
        unexplained += !edge;
      }
    EXPECT_GT(differing, 0u) << "the edge pass changed nothing";
    EXPECT_EQ(unexplained, 0u) << "of " << differing << " pixels that differ from the box filter's";
  }
}

// At the host's loop limit for the coverage filter (checkLoopLimit with two traces: 120 lights
// and 264 objects every ray tests), the main kernel and the edge pass stay within lavapipe's
// loop budget, which the kernels count (a pass over it throws LoopBudgetError), and the edge
// pass changes the pixels the horizon and the silhouettes cross.
TEST_F(CoverageTest, RendersAtTheLoopLimit) {
  std::string text = R"(
camera { eye = (0, 1, 6); lookat = (0, 0.6, 0); up = (0, 1, 0); fov = 40; }
background = (0.1, 0.2, 0.6);
)";
  for (int i = 0; i < 256; ++i) text += "plane { normal = (0, 1, 0); distance = " + std::to_string(-i) + "; }\n";
  for (int i = 0; i < 8; ++i) text += "sphere { center = (" + std::to_string(i - 3.5) + ", 0.5, 0); radius = 0.4; }\n";
  for (int i = 0; i < 120; ++i) text += "light { position = (0, 10, 4); color = (0.008, 0.008, 0.008); }\n";
  const Scene scene = parseSceneText(text, "limit.cfg");
  ASSERT_NO_THROW(checkLoopLimit(scene, 2));
  const std::vector<float> box = render(scene, 24, 18, OUTPUT_SHADED, 1, FILTER_BOX);
  const std::vector<float> coverage = render(scene, 24, 18, OUTPUT_SHADED, 1, FILTER_COVERAGE);
  size_t differing = 0;
  for (size_t i = 0; i < box.size(); ++i) differing += box[i] != coverage[i];
  EXPECT_GT(differing, 0u) << "the edge pass changed nothing";
}
