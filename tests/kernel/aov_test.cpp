// Passes (AOVs) from the pass kernel (RAYTEX_AOV, shaders/passes.glsl) through the renderer
// (Renderer::passMask, passPixels):
// - each pass at the pixel centres against the float64 reference (referencePasses,
//   host/reference/reference_render.cpp), the box filter's footprint, level and octaves against their
//   formulas on a plane seen head-on and in their trend on a plane receding to the horizon;
// - background pixels 0, coverage 0;
// - the shaded image beside them bit-identical to the render without passes; with N x N samples
//   (in one dispatch or progressive) the passes of the pixel centre, as with one sample; in bands
//   of rows the same passes as in one band.
#include "support/course_scene.h"
#include "support/files.h"
#include "support/format.h"
#include "support/gpu_fixture.h"
#include "support/reference_pixels.h"
#include "support/sphere_field.h"
#include "support/reference_passes.h"
#include "gpu_scene.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"
#include "renderer.h"
#include "texture_kinds.h"
#include "tile_kernels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Scene text is read as if from scenes/ (image paths relative to it).
Scene sceneText(const std::string& text) { return parseSceneText(text, kSourceDir + "/scenes/aov_test.cfg"); }
const std::string kUvGrid = "material m { texture = image { file = \"../textures/uv_grid.png\"; } }\n";

const uint32_t kAllPasses = (1u << AOV_COUNT) - 1u;
const uint32_t kPointPasses =
    (1u << AOV_UV) | (1u << AOV_NORMAL) | (1u << AOV_DEPTH) | (1u << AOV_POSITION) | (1u << AOV_ALBEDO);

// An image and its passes (by AOV_* bit; empty where not requested), whole, row 0 at the top.
struct PassRender {
  std::vector<float> image;
  std::vector<std::vector<float>> passes = std::vector<std::vector<float>>(AOV_COUNT);
  const float* at(Pass pass, size_t pixel) const { return &passes[uint32_t(pass)][pixel * 4]; }
};

struct PassOptions {
  uint32_t mask = kAllPasses;
  uint32_t samplesPerSide = 1;
  uint32_t filter = FILTER_POINT;
  bool progressive = false;  // one sample per dispatch (renderSample)
  uint32_t bandRows = 0;     // bands of this many rows (the buffers hold the whole image); 0: one
  bool tileKernels = false;  // the frame split among tile kernels (tile_kernels.h)
};

// Bytes of two float images differ at this many floats.
size_t differingFloats(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0;
  return n;
}

class AovTest : public RenderTest {
 protected:
  void TearDown() override {
    renderer_->passMask = 0;
    renderer_->accumulate = false;
    RenderTest::TearDown();
  }

  // Renders `scene` with the passes of `o.mask` (0: none) and reads every band back.
  PassRender renderPasses(const Scene& scene, uint32_t w, uint32_t h, const PassOptions& o) {
    renderer_->passMask = o.mask;
    renderer_->accumulate = o.progressive;
    renderer_->coverage = o.filter == FILTER_COVERAGE;
    GpuScene gpuScene = buildGpuScene(scene, w, h);
    uploadScene(*renderer_, gpuScene);
    KernelOptions kernel;
    kernel.textureFilter = o.filter;
    kernel.samplesPerSide = o.samplesPerSide;
    kernel.progressive = o.progressive;
    const KernelKey key = kernelKey(gpuScene, kernel);
    if (o.tileKernels) prepareTileKernels(*renderer_, key, tilePlan(gpuScene));
    else preparePipeline(*renderer_, key);
    const uint32_t wholeBand = renderer_->bandRows;
    if (o.bandRows) renderer_->bandRows = o.bandRows;
    PassRender out;
    out.image.assign(size_t(w) * h * 4, -1.0f);
    for (uint32_t bit = 0; bit < AOV_COUNT; ++bit)
      if (o.mask >> bit & 1u) out.passes[bit].assign(size_t(w) * h * 4, -1.0f);
    for (uint32_t first = 0; first < h; first += renderer_->bandRows) {
      selectBand(*renderer_, first);
      renderBand(o);
      readbackFrame(*renderer_);
      keepBand(out, size_t(first) * w * 4);
    }
    renderer_->bandRows = wholeBand;
    selectBand(*renderer_, 0);
    return out;
  }

  static TilePlan tilePlan(const GpuScene& g) {
    const TilePlan plan = planTileKernels(g, {g.shape.sphereKinds, g.shape.planeKinds});
    EXPECT_GE(plan.kernels.size(), 2u);
    return plan;
  }

  void renderBand(const PassOptions& o) {
    if (!o.progressive) return renderFrame(*renderer_);
    for (uint32_t i = 0; i < o.samplesPerSide * o.samplesPerSide; ++i) renderSample(*renderer_, i);
  }

  // Copies the selected band's image and passes into `out` from float `offset` on.
  void keepBand(PassRender& out, size_t offset) {
    const size_t floats = size_t(renderer_->width) * bandHeight(*renderer_) * 4;
    std::copy(framePixels(*renderer_), framePixels(*renderer_) + floats, out.image.begin() + ptrdiff_t(offset));
    for (uint32_t bit = 0; bit < AOV_COUNT; ++bit) {
      const float* pass = passPixels(*renderer_, Pass(bit));
      ASSERT_EQ(pass != nullptr, !out.passes[bit].empty()) << "pass " << bit;
      if (pass) std::copy(pass, pass + floats, out.passes[bit].begin() + ptrdiff_t(offset));
    }
  }
};

// Every pass of every background pixel is (0, 0, 0, 0); every pass's coverage is 1 elsewhere.
// Returns the background pixels seen.
int expectCoverage(const PassRender& r, const std::vector<ReferencePasses>& ref, const std::vector<bool>& reliable) {
  int background = 0, wrong = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    if (!reliable[i]) continue;
    const bool covered = ref[i].hit.kind != HIT_NONE;
    background += !covered;
    for (const std::vector<float>& pass : r.passes) {
      if (pass.empty()) continue;
      const float* p = &pass[i * 4];
      wrong += covered ? p[3] != 1.0f : (p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f || p[3] != 0.0f);
    }
  }
  EXPECT_EQ(wrong, 0) << "pass pixels whose coverage is wrong (or background not 0)";
  return background;
}

// The reference's passes at every pixel centre, and which pixels are reliable: away from
// silhouettes (a float ray may land on the other side), the far horizon (a pixel spans many
// tiles) and the poles (u is ill-conditioned).
std::vector<ReferencePasses> referenceAll(const Scene& scene, int w, int h, std::vector<bool>& reliable) {
  const std::map<std::string, ImageRGBA8> images = loadReferenceImages(scene);
  std::vector<ReferencePasses> out;
  reliable.clear();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      out.push_back(referencePasses(scene, images, w, h, x, y));
      const ReferenceHit& hit = out.back().hit;
      reliable.push_back(hit.edgeMargin >= 2e-3 && !(hit.kind == HIT_PLANE && hit.t > 60.0) &&
                         !(hit.kind == HIT_SPHERE && std::abs(hit.n.y) > 0.999));
    }
  return out;
}

const Material& hitMaterial(const Scene& scene, const ReferenceHit& hit) {
  return scene.materials[size_t(hit.kind == HIT_PLANE ? scene.planes[size_t(hit.index)].material
                                                      : scene.spheres[size_t(hit.index)].material)];
}

// Within float rounding of a checker's edge, where the kernel's point sample may take the
// other colour.
bool nearCheckEdge(const Material& m, const ReferencePasses& r) {
  if (m.texture.kind != TextureKind::Checker) return false;
  const double sq = std::max(std::round(double(m.texture.squares)), 1.0);
  for (double x : {r.coord.x * sq, r.coord.y * sq})
    if (std::abs(x - std::round(x)) < 1e-4) return true;
  return false;
}

double maxDifference(const float* g, glm::dvec3 ref) {
  double d = 0.0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(double(g[c]) - ref[c]));
  return d;
}

// Worst differences of the surface passes from the reference, over reliable covered pixels.
struct SurfaceErrors {
  double depth = 0.0, position = 0.0, normal = 0.0, coord = 0.0, albedo = 0.0, imageAlbedo = 0.0;
  int checked = 0;
};

SurfaceErrors surfaceErrors(const Scene& scene, const PassRender& r, const std::vector<ReferencePasses>& ref,
                            const std::vector<bool>& reliable) {
  const std::vector<float> world =
      worldPositions(r.passes[AOV_POSITION].data(), ref.size(), glm::dvec3(scene.camera.eye));
  SurfaceErrors e;
  for (size_t i = 0; i < ref.size(); ++i) {
    const ReferencePasses& p = ref[i];
    if (!reliable[i] || p.hit.kind == HIT_NONE) continue;
    ++e.checked;
    const Material& m = hitMaterial(scene, p.hit);
    e.depth = std::max(e.depth, std::abs(double(r.at(Pass::Depth, i)[0]) - p.depth) / p.depth);
    e.position = std::max(e.position, maxDifference(&world[i * 4], p.position) / p.depth);
    e.normal = std::max(e.normal, maxDifference(r.at(Pass::Normal, i), p.normal));
    const float* c = r.at(Pass::Uv, i);
    const bool solid = m.texture.kind != TextureKind::None && isSolidTexture(m.texture.kind);
    e.coord = std::max(e.coord, solid ? maxDifference(c, p.coord)
                                      : std::max(coordinateDistance(c[0], p.coord.x), coordinateDistance(c[1], p.coord.y)));
    if (nearCheckEdge(m, p)) continue;
    double& albedo = m.texture.kind == TextureKind::Image ? e.imageAlbedo : e.albedo;
    albedo = std::max(albedo, maxDifference(r.at(Pass::Albedo, i), p.albedo));
  }
  return e;
}

// uv, normal, depth, position and albedo at every reliable pixel centre of the course scene
// (2D and solid kinds on both shapes, an image, noise) equal the float64 reference's; the
// background is 0. Tolerances, from the float32 kernel's rounding (2^-24 = 6e-8 per operation,
// a few dozen operations from the camera to the hit): depth and position within 1e-5 of t
// (measured 2.9e-7 and 2.8e-7); the unit normal within 1e-5 per component (measured 1.6e-6);
// the coordinates within 1e-4 (measured 2.1e-6); procedural albedo within 2e-3 (noise's float
// lattice arithmetic, as AlbedoTest.TextureColourMatchesDoubleReference; measured 1e-4) and image
// albedo within 0.02 (8-bit texels, the driver's bilinear weights; measured 1.2e-3).
TEST_F(AovTest, SurfacePassesMatchDoubleReferenceAtPixelCentres) {
  const int w = 96, h = 72;
  const std::pair<const char*, const char*> materials[] = {
      {"aChecker", "aMarble"}, {"aSolidChecker", "aChecker"}, {"anImage", "aNoise"}};
  for (const auto& [sphere, plane] : materials) {
    SCOPED_TRACE(std::string(sphere) + " on the sphere, " + plane + " on the plane");
    Scene scene = courseScene(sphere, plane);
    PassRender r = renderPasses(scene, w, h, {kPointPasses});
    std::vector<bool> reliable;
    const std::vector<ReferencePasses> ref = referenceAll(scene, w, h, reliable);
    EXPECT_GT(expectCoverage(r, ref, reliable), 0);
    const SurfaceErrors e = surfaceErrors(scene, r, ref, reliable);
    EXPECT_GT(e.checked, w * h / 2);
    EXPECT_LT(e.depth, 1e-5) << "depth, relative";
    EXPECT_LT(e.position, 1e-5) << "world position, relative to the depth";
    EXPECT_LT(e.normal, 1e-5) << "facing normal";
    EXPECT_LT(e.coord, 1e-4) << "uv or solid coordinate";
    EXPECT_LT(e.albedo, 2e-3) << "procedural albedo";
    EXPECT_LT(e.imageAlbedo, 0.02) << "image albedo";
  }
}

// The normal pass faces the eye: seen from below, the plane's normal points down; from inside a
// sphere, inward.
TEST_F(AovTest, NormalFacesTheEye) {
  Scene scene = sceneText(
      "material m { diffuse = (0.5, 0.5, 0.5); }\n"
      "camera { eye = (0, -1, 0); lookat = (0, -1, -1); up = (0, 1, 0); fov = 60; }\n"
      "plane { normal = (0, 1, 0); distance = 0; m; }\n"
      "sphere { center = (3, -1, -4); radius = 1; m; }\n"
      "sphere { center = (0, -1, -20); radius = 100; m; }\n");
  const int w = 32, h = 24;
  PassRender r = renderPasses(scene, w, h, {1u << AOV_NORMAL});
  std::vector<bool> reliable;
  const std::vector<ReferencePasses> ref = referenceAll(scene, w, h, reliable);
  int below = 0, inside = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    if (!reliable[i] || ref[i].hit.kind == HIT_NONE) continue;
    const glm::dvec3 g(r.at(Pass::Normal, i)[0], r.at(Pass::Normal, i)[1], r.at(Pass::Normal, i)[2]);
    const glm::dvec3 toEye = glm::dvec3(scene.camera.eye) - ref[i].position;
    EXPECT_GT(glm::dot(g, toEye), 0.0) << "pixel " << i;
    below += ref[i].hit.kind == HIT_PLANE;
    inside += ref[i].hit.kind == HIT_SPHERE && ref[i].hit.index == 1;
  }
  EXPECT_GT(below, 50);
  EXPECT_GT(inside, 50);
}

// The shaded image written beside the passes is the image without them, bit for bit: point and
// box textures, one sample and N x N, with the sphere tree; and the coverage filter's (one sample
// per dispatch with N x N, as raytex render), whose passes are the box filter's.
TEST_F(AovTest, ShadedImageIsBitIdenticalWithPasses) {
  struct Case {
    const char* sphere;
    uint32_t samplesPerSide, filter;
  };
  const int w = 64, h = 48;
  for (const Case& c : {Case{"aSolidChecker", 1, FILTER_POINT}, Case{"anImage", 2, FILTER_POINT},
                        Case{"anImage", 1, FILTER_BOX}, Case{"aMarble", 2, FILTER_BOX},
                        Case{"aMarble", 1, FILTER_COVERAGE}, Case{"anImage", 2, FILTER_COVERAGE}}) {
    SCOPED_TRACE(std::string(c.sphere) + ", " + std::to_string(c.samplesPerSide) + " per side, filter " +
                 std::to_string(c.filter));
    Scene scene = courseScene(c.sphere, "aWood");
    const bool perSample = c.filter == FILTER_COVERAGE && c.samplesPerSide > 1;
    const PassRender without = renderPasses(scene, w, h, {0, c.samplesPerSide, c.filter, perSample});
    const PassRender with = renderPasses(scene, w, h, {kAllPasses, c.samplesPerSide, c.filter, perSample});
    EXPECT_EQ(differingFloats(with.image, without.image), 0u);
    EXPECT_EQ(countNonFinite(with.image), 0u);
    if (c.filter != FILTER_COVERAGE) continue;
    const PassRender box = renderPasses(scene, w, h, {kAllPasses, c.samplesPerSide, FILTER_BOX});
    EXPECT_GT(differingFloats(with.image, box.image), 0u) << "the edge pass changed nothing";
    for (uint32_t bit = 0; bit < AOV_COUNT; ++bit)
      EXPECT_EQ(differingFloats(with.passes[bit], box.passes[bit]), 0u) << passInfo(Pass(bit)).name;
  }
  Scene tree = field(40, "(0, 1, 6)");
  const PassRender without = renderPasses(tree, w, h, {0, 1, FILTER_BOX});
  const PassRender with = renderPasses(tree, w, h, {kAllPasses, 1, FILTER_BOX});
  EXPECT_EQ(differingFloats(with.image, without.image), 0u) << "sphere tree";
}

// With N x N samples the passes are the pixel centre's, as with one sample (the kernel traces
// the centre once more), in one dispatch and progressive; the image is the one without passes.
TEST_F(AovTest, SupersampledPassesComeFromThePixelCentre) {
  const int w = 64, h = 48;
  Scene scene = courseScene("anImage", "aTurbulence");
  const PassRender one = renderPasses(scene, w, h, {kAllPasses, 1, FILTER_BOX});
  for (bool progressive : {false, true}) {
    SCOPED_TRACE(progressive ? "progressive" : "one dispatch");
    const PassRender without = renderPasses(scene, w, h, {0, 2, FILTER_BOX, progressive});
    const PassRender with = renderPasses(scene, w, h, {kAllPasses, 2, FILTER_BOX, progressive});
    EXPECT_EQ(differingFloats(with.image, without.image), 0u) << "the shaded image";
    EXPECT_GT(differingFloats(with.image, one.image), 0u) << "2 x 2 samples shade differently";
    for (uint32_t bit = 0; bit < AOV_COUNT; ++bit)
      EXPECT_EQ(differingFloats(with.passes[bit], one.passes[bit]), 0u) << passInfo(Pass(bit)).name;
  }
}

// Bands of 7 rows (the last shorter) give the passes of one band, and its image.
TEST_F(AovTest, BandsGiveTheSamePassesAsOneBand) {
  const uint32_t w = 64, h = 50;
  Scene scene = courseScene("aMarble", "anImage");
  const PassRender whole = renderPasses(scene, w, h, {kAllPasses, 2, FILTER_BOX});
  const PassRender banded = renderPasses(scene, w, h, {kAllPasses, 2, FILTER_BOX, false, 7});
  EXPECT_EQ(differingFloats(banded.image, whole.image), 0u);
  for (uint32_t bit = 0; bit < AOV_COUNT; ++bit)
    EXPECT_EQ(differingFloats(banded.passes[bit], whole.passes[bit]), 0u) << passInfo(Pass(bit)).name;
}

// A frame split among tile kernels, each specialised to its tiles' kinds, writes the passes of
// the one kernel, beside the image without passes.
TEST_F(AovTest, TileKernelsWriteThePassesOfTheOneKernel) {
  const uint32_t w = 160, h = 96;
  Scene scene = field(8, "(2, -1.9, 3)");
  const PassRender one = renderPasses(scene, w, h, {kAllPasses, 1, FILTER_BOX});
  const PassRender tiles = renderPasses(scene, w, h, {kAllPasses, 1, FILTER_BOX, false, 0, true});
  const PassRender without = renderPasses(scene, w, h, {0, 1, FILTER_BOX, false, 0, true});
  EXPECT_EQ(differingFloats(tiles.image, without.image), 0u);
  for (uint32_t bit = 0; bit < AOV_COUNT; ++bit)
    EXPECT_EQ(differingFloats(tiles.passes[bit], one.passes[bit]), 0u) << passInfo(Pass(bit)).name;
}

// The box filter's footprint on the course scene equals the reference's finite differences
// (ReferencePasses::footprint): on the plane, where they are exact, within 1e-4 relative (float
// rounding of the differential rays, up to 30 units away; measured 1.5e-5); on the sphere, where
// the reference's central difference over a pixel's step differs from the derivative by
// O(step^2 / r^2), within 1 % (measured 0.3 %) away from the silhouette (view within 72 degrees
// of the normal) and the poles (|n_y| <= 0.9), where a step spans enough of the sphere for the
// difference to reach 9 %. 2D (checker) and solid (solid_checker) kinds on each shape.
TEST_F(AovTest, FootprintMatchesDoubleReference) {
  const int w = 96, h = 72;
  for (const auto& [sphere, plane] : {std::pair{"aChecker", "aSolidChecker"}, std::pair{"aSolidChecker", "aChecker"}}) {
    SCOPED_TRACE(std::string(sphere) + " on the sphere, " + plane + " on the plane");
    Scene scene = courseScene(sphere, plane);
    PassRender r = renderPasses(scene, w, h, {1u << AOV_FOOTPRINT, 1, FILTER_BOX});
    std::vector<bool> reliable;
    const std::vector<ReferencePasses> ref = referenceAll(scene, w, h, reliable);
    double worst[3] = {0.0, 0.0, 0.0};
    int checked[3] = {0, 0, 0};
    for (size_t i = 0; i < ref.size(); ++i) {
      const int kind = ref[i].hit.kind;
      if (!reliable[i] || kind == HIT_NONE || ref[i].hit.t > 30.0) continue;
      const float* g = r.at(Pass::Footprint, i);
      const glm::dvec3 view = glm::normalize(glm::dvec3(scene.camera.eye) - ref[i].position);
      if (kind == HIT_SPHERE && (glm::dot(view, ref[i].normal) < 0.3 || std::abs(ref[i].hit.n.y) > 0.9)) continue;
      for (int a = 0; a < 2; ++a)
        worst[kind] = std::max(worst[kind], std::abs(double(g[a]) - ref[i].footprint[a]) / ref[i].footprint[a]);
      ++checked[kind];
    }
    EXPECT_GT(checked[HIT_PLANE], w * h / 5);
    EXPECT_GT(checked[HIT_SPHERE], w * h / 10);
    EXPECT_LT(worst[HIT_PLANE], 1e-4) << "plane, relative";
    EXPECT_LT(worst[HIT_SPHERE], 1e-2) << "sphere, relative";
  }
}

// A plane seen head-on from height 2 (fov 40, 64 x 48): every pixel's step is the same on it,
// 2 * 2 tan(20 deg) / 48 world units, so the footprint is that over tex_scale on both axes; the
// uv_grid image (512 x 256, one image per texture unit) is read at
// level log2(256 * footprint) - log2(3) / 2 (its rows are the minor axis: kinds/image.glsl,
// imageBox, two probes along its columns), clamped to 0 where that is negative (magnified);
// turbulence keeps the octaves whose footprint, sqrt(2) * footprint * scale lattice cells at
// octave 0 and twice that at each next one, stays under 4 cells (noise.glsl, octaveWeight).
// Tolerances: 1e-4 relative for widths and 1e-4 for the level (float rounding of the camera and
// the differential rays; measured 4.5e-6 and 6.6e-6).
TEST_F(AovTest, HeadOnPlaneFootprintLodAndOctavesMatchTheirFormulas) {
  const int w = 64, h = 48;
  const double step = 2.0 * 2.0 * std::tan(20.0 * M_PI / 180.0) / h;
  for (double texScale : {20.0, 1.0}) {
    SCOPED_TRACE("tex_scale " + fmtG(texScale));
    const std::string camera = "camera { eye = (0.3, 2, 0.1); lookat = (0.3, 0, 0.1); up = (0, 0, -1); fov = 40; }\n";
    const std::string plane = "plane { normal = (0, 1, 0); distance = 0; tex_scale = " + fmtG(texScale) + "; m; }\n";
    Scene image = sceneText(kUvGrid + camera + plane);
    Scene turbulence = sceneText("material m { texture = turbulence { scale = 2; octaves = 8; } }\n" + camera + plane);
    const uint32_t mask = (1u << AOV_FOOTPRINT) | (1u << AOV_LOD) | (1u << AOV_OCTAVES);
    PassRender ri = renderPasses(image, w, h, {mask, 1, FILTER_BOX});
    PassRender rt = renderPasses(turbulence, w, h, {mask, 1, FILTER_BOX});
    const double a = step / texScale;
    const double lod = std::clamp(std::log2(256.0 * a) - 0.5 * std::log2(3.0), 0.0, 9.0);
    int octaves = 0;
    while (octaves < 8 && std::sqrt(2.0) * a * 2.0 * std::exp2(octaves) < 4.0) ++octaves;
    double worstWidth = 0.0, worstLod = 0.0;
    int wrongOctaves = 0;
    for (size_t i = 0; i < size_t(w) * h; ++i) {
      for (const PassRender* r : {&ri, &rt})
        for (int c = 0; c < 2; ++c) worstWidth = std::max(worstWidth, std::abs(r->at(Pass::Footprint, i)[c] / a - 1.0));
      worstLod = std::max(worstLod, std::abs(ri.at(Pass::Lod, i)[0] - lod));
      wrongOctaves += rt.at(Pass::Octaves, i)[0] != float(octaves);
      EXPECT_EQ(ri.at(Pass::Octaves, i)[0], 0.0f);
      EXPECT_EQ(rt.at(Pass::Lod, i)[0], 0.0f);
    }
    EXPECT_LT(worstWidth, 1e-4) << "footprint " << fmtG(a);
    EXPECT_LT(worstLod, 1e-4) << "level " << fmtG(lod);
    EXPECT_EQ(wrongOctaves, 0) << "octaves " << octaves;
  }
}

// A plane receding to the horizon (camera 1 above it, 8 degrees down): up the middle column,
// from the nearest row to the horizon, the footprint widths grow, the image's level grows from 0
// (magnified near the camera) and turbulence keeps fewer octaves. Non-strict steps: neighbouring
// rows may share a level or an octave count (and a level within 1e-4: float rounding).
TEST_F(AovTest, LodAndOctavesFallAndFootprintGrowsWithDistance) {
  const int w = 64, h = 48;
  const std::string rest = "camera { eye = (0, 1, 0); lookat = (0, 0.8595, -1); up = (0, 1, 0); fov = 60; }\n"
                           "plane { normal = (0, 1, 0); distance = 0; tex_scale = 20; m; }\n";
  Scene image = sceneText(kUvGrid + rest);
  Scene turbulence = sceneText("material m { texture = turbulence { scale = 8; octaves = 8; } }\n" + rest);
  const uint32_t mask = (1u << AOV_FOOTPRINT) | (1u << AOV_LOD) | (1u << AOV_OCTAVES);
  PassRender ri = renderPasses(image, w, h, {mask, 1, FILTER_BOX});
  PassRender rt = renderPasses(turbulence, w, h, {mask, 1, FILTER_BOX});
  const size_t x = w / 2;
  int rows = 0;
  for (int y = h - 1; y > 0 && ri.at(Pass::Lod, size_t(y - 1) * w + x)[3] == 1.0f; --y, ++rows) {
    const size_t near = size_t(y) * w + x, far = size_t(y - 1) * w + x;
    EXPECT_GE(ri.at(Pass::Lod, far)[0], ri.at(Pass::Lod, near)[0] - 1e-4f) << "row " << y;
    EXPECT_LE(rt.at(Pass::Octaves, far)[0], rt.at(Pass::Octaves, near)[0]) << "row " << y;
    for (int c = 0; c < 2; ++c) EXPECT_GT(ri.at(Pass::Footprint, far)[c], ri.at(Pass::Footprint, near)[c]) << "row " << y;
  }
  const size_t bottom = size_t(h - 1) * w + x, top = size_t(h - 1 - rows) * w + x;
  EXPECT_GT(rows, h / 3);
  EXPECT_EQ(ri.at(Pass::Lod, bottom)[0], 0.0f) << "magnified";
  EXPECT_GT(ri.at(Pass::Lod, top)[0], 2.0f) << "minified";
  EXPECT_GT(rt.at(Pass::Octaves, bottom)[0], rt.at(Pass::Octaves, top)[0]);
  EXPECT_GT(ri.at(Pass::Footprint, top)[1], 100.0f * ri.at(Pass::Footprint, bottom)[1]);
}

// Without passes the renderer prepares exactly the key it is given (less its device's loop
// budget) and the pass buffer is a placeholder; with passes the key carries the mask, and each
// requested pass is a plane of the band in bit order.
TEST_F(AovTest, WithoutPassesTheKernelKeyIsUnchanged) {
  const uint32_t w = 32, h = 24;
  GpuScene gpuScene = buildGpuScene(courseScene("aChecker"), w, h);
  KernelKey key = kernelKey(gpuScene, KernelOptions{});
  EXPECT_EQ(key.passMask, 0u);
  uploadScene(*renderer_, gpuScene);
  preparePipeline(*renderer_, key);
  key.loopBudget = renderer_->pipelineKey.loopBudget;
  EXPECT_TRUE(renderer_->pipelineKey == key);
  EXPECT_EQ(renderer_->passes.size, 16u);
  EXPECT_EQ(passPixels(*renderer_, Pass::Uv), nullptr);

  renderer_->passMask = (1u << AOV_NORMAL) | (1u << AOV_LOD);
  uploadScene(*renderer_, gpuScene);
  preparePipeline(*renderer_, key);
  EXPECT_EQ(renderer_->pipelineKey.passMask, renderer_->passMask);
  EXPECT_FALSE(renderer_->pipelineKey == key);
  EXPECT_EQ(renderer_->passes.size, VkDeviceSize(w) * h * 16 * 2);
  EXPECT_EQ(passPixels(*renderer_, Pass::Lod) - passPixels(*renderer_, Pass::Normal), ptrdiff_t(w) * h * 4);
  EXPECT_EQ(passPixels(*renderer_, Pass::Uv), nullptr);
}

// worldPositions adds the eye in double to covered pixels and leaves the background 0.
TEST(WorldPosition, AddsTheEyeWhereCovered) {
  const float pass[] = {1.0f, -2.0f, 0.5f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  const std::vector<float> world = worldPositions(pass, 2, glm::dvec3(1.0e4, 0.25, -3.0));
  EXPECT_EQ(world, (std::vector<float>{10001.0f, -1.75f, -2.5f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f}));
}

}  // namespace
