// Upright images and texture placement (docs/textures.md, "Image orientation" and "Texture
// placement"), on a Vulkan device (lavapipe in CI) with validation on, against the float64
// oracle (host/reference/mapping.cpp, reference*.cpp) and against the orientation rule itself.
#include "support/gpu_fixture.h"
#include "atomic_file.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"
#include "support/course_scene.h"
#include "support/files.h"
#include "support/reference_rmse.h"
#include "texture.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace {

// Quadrant colours of the test image, in linear light (8-bit 0 and 255 are exact in sRGB).
const glm::dvec3 kTopLeft(1, 0, 0), kTopRight(0, 1, 0), kBottomLeft(0, 0, 1), kBottomRight(1, 1, 1);

// A w x h image of `columns` vertical stripes whose colour is stripeColour(i), or (columns 0)
// of four quadrants: red top left, green top right, blue bottom left, white bottom right.
ImageRGBA8 testImage(int w, int h, int columns) {
  ImageRGBA8 image{w, h, std::vector<uint8_t>(size_t(w) * h * 4, 255)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec3 c = columns > 0 ? glm::dvec3(double(x * columns / w) / (columns - 1), 0.0, 1.0)
                     : y < h / 2 ? (x < w / 2 ? kTopLeft : kTopRight)
                                 : (x < w / 2 ? kBottomLeft : kBottomRight);
      uint8_t* p = &image.pixels[(size_t(y) * w + x) * 4];
      for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(255.0 * linearToSrgb(c[k])));
    }
  return image;
}

// A scene in a fresh directory holding quadrants.png and stripes.png (9 stripes); every
// pixel's colour is its texture colour (ambient only).
Scene placementScene(const std::string& objects, const std::string& camera, const std::string& texture) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = freshTempDir("placement_test");
    writePngAtomic((d / "quadrants.png").string(), testImage(64, 64, 0));
    writePngAtomic((d / "stripes.png").string(), testImage(90, 45, 9));
    return d;
  }();
  return parseSceneText("material m { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0); texture = " +
                            texture + "; }\nambient_light = (1, 1, 1);\n" + camera + objects,
                        (dir / "scene.cfg").string());
}

std::string vec(glm::dvec3 v) {
  return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

std::string cameraText(glm::dvec3 eye, glm::dvec3 lookat, glm::dvec3 up, double fov) {
  return "camera { eye = " + vec(eye) + "; lookat = " + vec(lookat) + "; up = " + vec(up) +
         "; fov = " + std::to_string(fov) + "; }\n";
}

// The oracle's texture colour of the primary ray through pixel (x, y).
glm::dvec3 referenceAlbedo(const Scene& scene, const std::map<std::string, ImageRGBA8>& images, int w, int h,
                           int x, int y) {
  ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, referenceRayDirection(scene.camera, w, h, x, y));
  if (hit.kind == HIT_NONE) return glm::dvec3(-1.0);
  const TextureDesc& t = scene.materials[0].texture;
  if (t.kind == TextureKind::Image) return sampleImageReference(images.at(t.imagePath), hit.tc, t.wrap);
  return textureColorReference(t, hit.tc);
}

glm::dvec3 gpuPixel(const std::vector<float>& rgba, int w, int x, int y) {
  const float* p = &rgba[(size_t(y) * w + x) * 4];
  return glm::dvec3(p[0], p[1], p[2]);
}

double distance(glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b); }

class PlacementTest : public RenderTest {};

// Part 4: seen from the side its normal points to, an image on a plane reads upright and
// unmirrored: the top along world +y projected onto the plane (-z where |n_y| >= sqrt(1/2)),
// the right along up x n. The camera looks against n with that up (so its right is up x n) at
// the centre of one image tile, which fills the view: each screen quadrant must show the same
// image quadrant, on the GPU (point and box) and in the oracle. The sphere, seen from +x with
// north up, shows the image's centre (u = 0.5 at phi = 0), also unmirrored.
TEST_F(PlacementTest, ImagesAreUprightOnEveryPlaneAndTheSphere) {
  const int w = 48, h = 48;
  const double s = 4.0;  // one tile 4 x 4; the view is 2.2 wide at distance 3
  std::vector<glm::dvec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  normals.push_back(glm::normalize(glm::dvec3(1, 1, 1)));
  struct Case {
    std::string name;
    Scene scene;
  };
  std::vector<Case> cases;
  for (glm::dvec3 n : normals) {
    glm::dvec3 world = std::abs(n.y) >= std::sqrt(0.5) ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    glm::dvec3 up = glm::normalize(world - glm::dot(world, n) * n);
    glm::dvec3 right = glm::cross(up, n);
    glm::dvec3 origin = 0.5 * n;  // plane x.n = 0.5
    glm::dvec3 centre = origin + 0.5 * s * right - 0.5 * s * up;  // the image's origin is its top-left corner
    cases.push_back({"plane " + vec(n),
                     placementScene("plane { normal = " + vec(n) + "; distance = 0.5; tex_scale = 4; m; }\n",
                                    cameraText(centre + 3.0 * n, centre, up, 40.0),
                                    "image { file = \"quadrants.png\"; }")});
  }
  cases.push_back({"sphere", placementScene("sphere { center = (0, 0, 0); radius = 1; m; }\n",
                                            cameraText({4, 0, 0}, {0, 0, 0}, {0, 1, 0}, 30.0),
                                            "image { file = \"quadrants.png\"; }")});
  for (Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::map<std::string, ImageRGBA8> images = loadReferenceImages(c.scene);
    std::vector<float> point = render(c.scene, w, h, OUTPUT_ALBEDO);
    std::vector<float> box = render(c.scene, w, h, OUTPUT_ALBEDO, 1, FILTER_BOX);
    const struct {
      int x, y;
      glm::dvec3 colour;
    } quadrants[] = {{w / 4, h / 4, kTopLeft}, {3 * w / 4, h / 4, kTopRight},
                     {w / 4, 3 * h / 4, kBottomLeft}, {3 * w / 4, 3 * h / 4, kBottomRight}};
    for (const auto& q : quadrants) {
      SCOPED_TRACE("pixel " + std::to_string(q.x) + ", " + std::to_string(q.y));
      EXPECT_LT(distance(gpuPixel(point, w, q.x, q.y), q.colour), 0.02);
      EXPECT_LT(distance(gpuPixel(box, w, q.x, q.y), q.colour), 0.02);
      EXPECT_LT(distance(referenceAlbedo(c.scene, images, w, h, q.x, q.y), q.colour), 1e-9);
    }
  }
}

// The four-quadrant image tiles seamlessly on an oblique plane (normal (1, 1, 1)) seen from
// 1e5 away from the origin: the GPU's image lookup, rotated on the host in double, matches the
// oracle's at every pixel away from the quadrant borders.
TEST_F(PlacementTest, ObliqueImageMatchesTheOracleFarFromTheOrigin) {
  const int w = 64, h = 48;
  const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 1));
  const glm::dvec3 far(1.0e5, -2.0e5, 0.7e5);
  const double d = glm::dot(far, n);
  Scene scene = placementScene("plane { normal = (1, 1, 1); distance = " + std::to_string(d) +
                                   "; tex_scale = 0.7; tex_rotate = (10, 20, 30); tex_offset = (0.3, 0.6, 0); m; }\n",
                               cameraText(far + 4.0 * n + glm::dvec3(0.3, 0, 0), far, {0, 1, 0}, 50.0),
                               "image { file = \"quadrants.png\"; }");
  std::map<std::string, ImageRGBA8> images = loadReferenceImages(scene);
  std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);
  int checked = 0, wrong = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, referenceRayDirection(scene.camera, w, h, x, y));
      ASSERT_EQ(hit.kind, HIT_PLANE);
      glm::dvec2 st = hit.tc.image;
      auto nearBorder = [](double v) { return std::min({v, std::abs(v - 0.5), 1.0 - v}) < 0.03; };
      if (nearBorder(st.x) || nearBorder(st.y)) continue;
      ++checked;
      glm::dvec3 expected = sampleImageReference(images.begin()->second, hit.tc);
      wrong += distance(gpuPixel(gpu, w, x, y), expected) > 0.02;
    }
  EXPECT_GT(checked, w * h / 2);
  EXPECT_EQ(wrong, 0);
}

// Part 5: tex_rotate = (0, 180, 0) turns the map half a turn about the polar axis, and
// (0, -90, 0) brings the map's middle column (Greenwich on an Earth map) to a camera on +z.
// The stripe image has 9 stripes: the sphere's centre pixel seen from +z shows stripe 2 (u =
// 0.75, column 0.25), 6 half a turn later, 4 at Greenwich; GPU and oracle.
TEST_F(PlacementTest, RotatedSphereTurnsTheMapAboutItsAxis) {
  const int w = 33, h = 33;  // odd: the centre pixel's ray hits n = (0, 0, 1)
  const struct {
    const char* rotate;
    int stripe;
  } cases[] = {{"(0, 0, 0)", 2}, {"(0, 180, 0)", 6}, {"(0, -90, 0)", 4}, {"(0, 45, 0)", 1}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.rotate);
    Scene scene = placementScene(std::string("sphere { center = (0, 0, 0); radius = 1; tex_rotate = ") + c.rotate +
                                     "; m; }\n",
                                 cameraText({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 30.0), "image { file = \"stripes.png\"; }");
    std::map<std::string, ImageRGBA8> images = loadReferenceImages(scene);
    glm::dvec3 expected(c.stripe / 8.0, 0.0, 1.0);
    std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);
    EXPECT_LT(distance(gpuPixel(gpu, w, w / 2, h / 2), expected), 0.02);
    EXPECT_LT(distance(referenceAlbedo(scene, images, w, h, w / 2, h / 2), expected), 0.01);
  }
}

// Every kind with a placement on both shapes: the kernel's texture colour and coordinates
// equal the oracle's at every reliable pixel (away from silhouettes, the sphere's poles and
// texture discontinuities), point-sampled.
TEST_F(PlacementTest, PlacedTexturesMatchTheOracle) {
  const int w = 96, h = 72;
  const char* const textures[] = {"image { file = \"quadrants.png\"; }", "checker { squares = 3; }",
                                  "solid_checker { squares = 3; }", "marble { scale = 2; }", "wood",
                                  "turbulence { octaves = 4; }"};
  const std::string objects =
      "sphere { center = (-1.2, 0, 0); radius = 1; tex_rotate = (30, -50, 20); tex_scale = 0.5; tex_offset = (0.25, "
      "0.4, 0); m; }\n"
      "sphere { center = (1.2, 0, 0); radius = 1; tex_rotate = (0, 0, 90); tex_offset = (0.3, 0, 0); m; }\n"
      "plane { normal = (0, 1, 0.2); distance = -1; tex_scale = 1.5; tex_rotate = (15, 35, -10); tex_offset = "
      "(0.5, 0.25, 0); m; }\n";
  for (const char* texture : textures) {
    SCOPED_TRACE(texture);
    Scene scene = placementScene(objects, cameraText({0, 2, 6}, {0, -0.3, 0}, {0, 1, 0}, 50.0), texture);
    std::map<std::string, ImageRGBA8> images = loadReferenceImages(scene);
    std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);
    const TextureKind kind = scene.materials[0].texture.kind;
    int checked = 0, wrong = 0;
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        glm::dvec3 eye = scene.camera.eye;
        ReferenceHit hit = referenceClosestHit(scene, eye, referenceRayDirection(scene.camera, w, h, x, y));
        if (hit.kind == HIT_NONE || hit.edgeMargin < 2e-3 || hit.t > 40.0) continue;
        if (hit.kind == HIT_SPHERE) {
          const Sphere& sp = scene.spheres[size_t(hit.index)];
          glm::dvec3 turned = glm::transpose(placementRotation(sp.placement.rotate)) * hit.n;
          if (std::abs(turned.y) > 0.99) continue;  // the poles: u is ill-conditioned
        }
        // Away from discontinuities: checks, quadrants, wood rings.
        auto nearEdge = [](double v, double cells) { return std::abs(v * cells - std::round(v * cells)) < 2e-3 * cells; };
        bool edge = false;
        if (kind == TextureKind::Image) edge = nearEdge(hit.tc.image.x, 2) || nearEdge(hit.tc.image.y, 2);
        if (kind == TextureKind::Checker) edge = nearEdge(hit.tc.uv.x, 3) || nearEdge(hit.tc.uv.y, 3);
        if (kind == TextureKind::SolidChecker)
          edge = nearEdge(hit.tc.solid.x, 3) || nearEdge(hit.tc.solid.y, 3) || nearEdge(hit.tc.solid.z, 3);
        if (kind == TextureKind::Wood) {
          double b = textureBlendReference(scene.materials[0].texture, hit.tc);
          edge = b < 0.02 || b > 0.98;
        }
        if (edge) continue;
        ++checked;
        double d = distance(gpuPixel(gpu, w, x, y), referenceAlbedo(scene, images, w, h, x, y));
        worst = std::max(worst, d);
        wrong += d > (kind == TextureKind::Image ? 0.03 : 0.01);
      }
    EXPECT_GT(checked, w * h / 3);
    EXPECT_LE(wrong, checked / 1000) << "worst " << worst;
  }
}

// Two spheres with the same marble, one with tex_offset: the offset sphere's colours are the
// oracle's with the offset, and differ from what the unplaced coordinate gives there.
TEST_F(PlacementTest, OffsetMarbleSpheresDiffer) {
  const int w = 96, h = 48;
  Scene scene = placementScene("sphere { center = (-1.1, 0, 0); radius = 1; m; }\n"
                               "sphere { center = (1.1, 0, 0); radius = 1; tex_offset = (0.7, 1.9, 3.1); m; }\n",
                               cameraText({0, 0, 7}, {0, 0, 0}, {0, 1, 0}, 30.0), "marble { scale = 3; }");
  std::map<std::string, ImageRGBA8> images;
  std::vector<float> gpu = render(scene, w, h, OUTPUT_ALBEDO);
  const TextureDesc& marble = scene.materials[0].texture;
  double offsetSum = 0.0, oracleWorst = 0.0;
  int onOffsetSphere = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye, referenceRayDirection(scene.camera, w, h, x, y));
      if (hit.kind != HIT_SPHERE || hit.edgeMargin < 2e-3) continue;
      glm::dvec3 g = gpuPixel(gpu, w, x, y);
      oracleWorst = std::max(oracleWorst, distance(g, referenceAlbedo(scene, images, w, h, x, y)));
      if (hit.index != 1) continue;
      ++onOffsetSphere;
      offsetSum += distance(g, textureColorReference(marble, sphereTexCoord(hit.n)));
    }
  ASSERT_GT(onOffsetSphere, w * h / 10);
  EXPECT_LT(oracleWorst, 0.01);
  EXPECT_GT(offsetSum / onOffsetSphere, 0.05) << "the offset sphere looks like the plain one";
}

// Filtering follows the placement: a rotated, finely scaled checker floor, box-filtered at
// 1 spp, is close to the 8x8-supersampled float64 reference, far closer than point sampling.
// Measured on lavapipe (RMSE point, box): checker 0.283, 0.040; solid_checker 0.232, 0.040;
// with footprints that skip the placement (neither turned nor divided by tex_scale) box was
// 0.138 and 0.113.
TEST_F(PlacementTest, RotatedScaledCheckerBoxFilterMatchesSupersampledReference) {
  const int w = 96, h = 72;
  for (const char* texture : {"checker { squares = 2; }", "solid_checker { squares = 2; }"}) {
    SCOPED_TRACE(texture);
    Scene scene = placementScene("plane { normal = (0, 1, 0); distance = 0; tex_scale = 0.2; tex_rotate = (0, 30, 0); "
                                 "tex_offset = (0.2, 0.1, 0); m; }\n",
                                 cameraText({0, 1.5, 3}, {0, 0, -3}, {0, 1, 0}, 60.0), texture);
    ReferenceImage ref = renderReference(scene, w, h, 8);
    std::vector<float> point = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT);
    std::vector<float> box = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX);
    double ePoint = rmseAgainstReference(point.data(), ref), eBox = rmseAgainstReference(box.data(), ref);
    printf("[placed-filter] %s: RMSE point %.4f, box %.4f\n", texture, ePoint, eBox);
    EXPECT_LT(eBox, 0.25 * ePoint);
    EXPECT_LT(eBox, 0.06);
  }
}

// Objects without placement render bit-identically whether the kernel applies placement
// (SPEC_TEXTURE_PLACEMENT on: the identity quaternion, tex_scale 1 and zero offsets read from
// the uniform blocks) or is specialised without it, for the course materials, point and box.
TEST_F(PlacementTest, IdentityPlacementIsExact) {
  const int w = 64, h = 48;
  for (const char* material : {"aSolidChecker", "aMarble", "anImage", "aChecker"}) {
    SCOPED_TRACE(material);
    Scene scene = courseScene(material);
    SceneShape with = sceneShape(scene), without = with;
    ASSERT_EQ(without.placed, 0u);
    with.placed = 1;
    for (uint32_t filter : {uint32_t(FILTER_POINT), uint32_t(FILTER_BOX)}) {
      std::vector<float> a = render(scene, w, h, OUTPUT_SHADED, 1, filter, &with);
      std::vector<float> b = render(scene, w, h, OUTPUT_SHADED, 1, filter, &without);
      EXPECT_TRUE(a == b) << "filter " << filter;
    }
  }
}

}  // namespace
