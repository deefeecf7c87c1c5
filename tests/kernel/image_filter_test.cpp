// Mipmapped image textures in the FILTER_BOX kernel: trilinear lookups over host-built mip
// chains at the footprint's level, against the float64 reference (bilinear level 0,
// supersampled: the box-filtered truth). Rendered on a Vulkan device (lavapipe in CI) with
// validation on; every image is checked for NaN/inf.
#include "image_file.h"
#include "mip_chain.h"
#include "srgb.h"
#include "atomic_file.h"
#include "parser.h"
#include "reference.h"
#include "reference_render.h"

#include "support/files.h"
#include "support/format.h"
#include "support/gpu_fixture.h"
#include "support/reference_pixels.h"
#include "support/reference_rmse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {


// Ambient light and ambient coefficient 1, no lights: every pixel is the texture colour.
std::string flatMaterial(const std::string& image) {
  return "material m { ambient = (1, 1, 1); diffuse = (0, 0, 0); specular = (0, 0, 0);"
         " texture = image { file = \"../textures/" + image + "\"; }; }\n"
         "ambient_light = (1, 1, 1);\nbackground = (0.5, 0.5, 0.5);\n";
}

Scene sceneFromText(const std::string& text) {
  return parseSceneText(text, kSourceDir + "/scenes/image_filter_test.cfg");
}

// The floor toward the horizon (camera 1 above the floor, 8
// degrees down, 60 degree fov), one image per `texScale` units.
Scene horizonScene(const std::string& image, double texScale) {
  return sceneFromText(flatMaterial(image) +
                       "camera { eye = (0, 1, 0); lookat = (0, 0.8594, -1); up = (0, 1, 0); fov = 60; }\n"
                       "plane { normal = (0, 1, 0); distance = 0; tex_scale = " + std::to_string(texScale) +
                       "; m; }\n");
}

// A unit sphere at the origin seen from `eye`.
Scene sphereScene(const std::string& image, const std::string& eye, const std::string& up, double fov) {
  return sceneFromText(flatMaterial(image) + "camera { eye = " + eye + "; lookat = (0, 0, 0); up = " + up +
                       "; fov = " + std::to_string(fov) + "; }\n"
                       "sphere { center = (0, 0, 0); radius = 1; m; }\n");
}

size_t countMask(const std::vector<bool>& mask) { return size_t(std::count(mask.begin(), mask.end(), true)); }

// PNGs for looking at (not read back): build/test-output/image_filter_<name>.png.
void writeImage(const std::string& name, const std::vector<float>& rgba, int w, int h) {
  writePngAtomic((testOutputDir() / ("image_filter_" + name + ".png")).string(), encodeSrgb(rgba.data(), w, h));
}

class ImageFilterTest : public RenderTest {};

// 1. Minification. Against a 16x16 float64 reference, over the pixels wholly on the object:
// filtered 1 spp is far below point 1 spp (moire on the floor, speckle on the far sphere), and
// filtered 2x2 below filtered 1 spp (the footprint shrinks with the sample spacing).
// Measured on lavapipe (RMSE, linear RGB; point 1 spp, point 4x4, box 1 spp, box 2x2):
//   floor_uv_grid       0.201  0.064   0.029   0.025
//   floor_earth         0.205  0.057   0.024   0.021
//   far_sphere_earth    0.053  0.0069  0.0073  0.0025
//   far_sphere_uv_grid  0.110  0.0079  0.020   0.013
// (isotropic trilinear, one lookup at log2 of the longer footprint axis, --image-filter
// trilinear: box 1 spp 0.084 on floor_earth and 0.060 on far_sphere_uv_grid, test 5; the
// principal-axis probes and the level bias make the difference). Limit: box 1 spp below a third
// of point 1 spp (measured 5.6x to 8.4x lower).
TEST_F(ImageFilterTest, MinifiedImagesBeatPointSampling) {
  struct Case {
    const char* name;
    Scene scene;
    int w, h, kind;
  } cases[] = {
      {"floor_uv_grid", horizonScene("uv_grid.png", 1.0), 128, 96, HIT_PLANE},
      {"floor_earth", horizonScene("earth.jpg", 2.0), 128, 96, HIT_PLANE},
      // 40 px across, about 16 texels of earth.jpg per pixel at the centre.
      {"far_sphere_earth", sphereScene("earth.jpg", "(2, 3, 8.5)", "(0, 1, 0)", 30.0), 96, 96, HIT_SPHERE},
      {"far_sphere_uv_grid", sphereScene("uv_grid.png", "(2, 3, 8.5)", "(0, 1, 0)", 30.0), 96, 96, HIT_SPHERE},
  };
  for (Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<bool> mask = interiorMask(c.scene, c.w, c.h, c.kind);
    ASSERT_GT(countMask(mask), size_t(c.w * c.h / 16));
    ReferenceImage ref = renderReference(c.scene, c.w, c.h, 16);
    ASSERT_EQ(ref.nonFinite, 0u);
    std::vector<float> point1 = render(c.scene, c.w, c.h, OUTPUT_SHADED, 1, FILTER_POINT);
    std::vector<float> point16 = render(c.scene, c.w, c.h, OUTPUT_SHADED, 4, FILTER_POINT);
    std::vector<float> box1 = render(c.scene, c.w, c.h, OUTPUT_SHADED, 1, FILTER_BOX);
    std::vector<float> box4 = render(c.scene, c.w, c.h, OUTPUT_SHADED, 2, FILTER_BOX);
    for (const auto* img : {&point1, &point16, &box1, &box4}) EXPECT_EQ(countNonFinite(*img), 0u);
    double ePoint1 = rmseAgainstReference((point1).data(), ref, &mask), ePoint16 = rmseAgainstReference((point16).data(), ref, &mask);
    double eBox1 = rmseAgainstReference((box1).data(), ref, &mask), eBox4 = rmseAgainstReference((box4).data(), ref, &mask);
    std::string numbers = fmt(ePoint1) + " " + fmt(ePoint16) + " " + fmt(eBox1) + " " + fmt(eBox4);
    RecordProperty(std::string(c.name) + "_rmse_point1_point16_box1_box4", numbers);
    printf("[minify] %-20s rmse point1 %s point16 %s box1 %s box4 %s (%zu px)\n", c.name, fmt(ePoint1).c_str(),
           fmt(ePoint16).c_str(), fmt(eBox1).c_str(), fmt(eBox4).c_str(), countMask(mask));
    writeImage(std::string(c.name) + "_box1", box1, c.w, c.h);
    writeImage(std::string(c.name) + "_point1", point1, c.w, c.h);
    writeImage(std::string(c.name) + "_ref", referenceToRgba(ref), c.w, c.h);
    EXPECT_LT(eBox1, ePoint1 / 3.0);
    EXPECT_LT(eBox4, eBox1);
  }
}

// Mean of the linear RGB channels of pixel i.
double grey(const std::vector<float>& img, size_t i) { return (img[i * 4] + img[i * 4 + 1] + img[i * 4 + 2]) / 3.0; }
double grey(const ReferenceImage& ref, size_t i) { return (ref.rgb[i * 3] + ref.rgb[i * 3 + 1] + ref.rgb[i * 3 + 2]) / 3.0; }

// Seam statistics over the rows where columns x0 - 4 .. x0 + 4 are all inside the sphere:
// `seam` is the mean |c(x0) - (c(x0 - 1) + c(x0 + 1)) / 2| (a line of another colour along
// the seam column raises it), `local` the mean |c(x) - c(x + 1)| over the neighbouring pairs
// that do not touch x0 (the image's own detail there).
struct SeamStats {
  double seam = 0.0, local = 0.0;
  int rows = 0;
};
template <typename Image>
SeamStats seamStats(const Image& img, const std::vector<bool>& mask, int w, int h, int x0) {
  SeamStats s;
  for (int y = 0; y < h; ++y) {
    bool inside = true;
    for (int x = x0 - 4; x <= x0 + 4; ++x) inside = inside && mask[size_t(y) * w + x];
    if (!inside) continue;
    auto c = [&](int x) { return grey(img, size_t(y) * w + x); };
    s.seam += std::abs(c(x0) - 0.5 * (c(x0 - 1) + c(x0 + 1)));
    double local = 0.0;
    for (int x : {x0 - 4, x0 - 3, x0 - 2, x0 + 1, x0 + 2, x0 + 3}) local += std::abs(c(x) - c(x + 1));
    s.local += local / 6.0;
    ++s.rows;
  }
  if (s.rows) {
    s.seam /= s.rows;
    s.local /= s.rows;
  }
  return s;
}

// 2. The sphere's u seam facing the camera, minified (the
// sphere 40 px across, ~16 texels per pixel): with analytic derivatives the seam column gets
// the same level as its neighbours, so no line of average colour. The camera looks along +x at
// the -x meridian (u = 0/1); the width is odd so the centre column's samples lie exactly on the
// seam. Limits: the notes' 3x for seam/local, and the seam column's RMSE against the reference
// under 2x that of the columns beside it. Measured (seam, local; RMSE seam column, nearby):
//   earth    1 spp 0.0008 0.0023; 0.0026 0.0077    2x2 0.0009 0.0028; 0.0019 0.0033
//   uv_grid  1 spp 0.0407 0.0387; 0.0072 0.0158    2x2 0.0444 0.0407; 0.0058 0.0057
// (uv_grid marks the seam with a red stripe: the reference has seam 0.044, local 0.040 too).
TEST_F(ImageFilterTest, SphereSeamHasNoLine) {
  const int w = 97, h = 97, x0 = w / 2;
  for (const char* image : {"earth.jpg", "uv_grid.png"}) {
    SCOPED_TRACE(image);
    Scene scene = sphereScene(image, "(-9.2, 0, 0)", "(0, 1, 0)", 30.0);
    std::vector<bool> mask = interiorMask(scene, w, h, HIT_SPHERE);
    ReferenceImage ref = renderReference(scene, w, h, 16);
    std::vector<float> box1 = render(scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX);
    std::vector<float> box4 = render(scene, w, h, OUTPUT_SHADED, 2, FILTER_BOX);
    EXPECT_EQ(countNonFinite(box1), 0u);
    EXPECT_EQ(countNonFinite(box4), 0u);
    writeImage(std::string("seam_") + image + "_box1", box1, w, h);
    writeImage(std::string("seam_") + image + "_ref", referenceToRgba(ref), w, h);
    SeamStats sRef = seamStats(ref, mask, w, h, x0);
    ASSERT_GT(sRef.rows, 20);
    for (const auto* img : {&box1, &box4}) {
      SeamStats s = seamStats(*img, mask, w, h, x0);
      // RMSE of the seam column and of the columns beside it, against the reference.
      std::vector<bool> seamCol(mask.size(), false), nearCols(mask.size(), false);
      for (int y = 0; y < h; ++y) {
        seamCol[size_t(y) * w + x0] = mask[size_t(y) * w + x0];
        for (int x : {x0 - 3, x0 - 2, x0 - 1, x0 + 1, x0 + 2, x0 + 3}) nearCols[size_t(y) * w + x] = mask[size_t(y) * w + x];
      }
      double eSeam = rmseAgainstReference((*img).data(), ref, &seamCol), eNear = rmseAgainstReference((*img).data(), ref, &nearCols);
      const char* name = img == &box1 ? "box1" : "box4";
      printf("[seam] %-12s %s: seam %s local %s (reference: seam %s local %s); rmse seam column %s, nearby %s\n",
             image, name, fmt(s.seam).c_str(), fmt(s.local).c_str(), fmt(sRef.seam).c_str(), fmt(sRef.local).c_str(),
             fmt(eSeam).c_str(), fmt(eNear).c_str());
      RecordProperty(std::string(image).substr(0, std::string(image).find('.')) + "_" + name +
                         "_seam_local_rmseSeam_rmseNear",
                     fmt(s.seam) + " " + fmt(s.local) + " " + fmt(eSeam) + " " + fmt(eNear));
      EXPECT_LT(s.seam, 3.0 * s.local) << name;
      EXPECT_LT(eSeam, 2.0 * eNear) << name;
    }
    // The check sees the failure it is for: a seam column of the image's mean colour (what a
    // level chosen from differenced u, |du| ~ 1, would give) fails it. Earth only: uv_grid
    // marks its seam with a red stripe, local detail that hides a mean-colour line (measured:
    // seam 0.073, local 0.039).
    if (std::string(image) != "earth.jpg") continue;
    ImageRGBA8 decoded;
    ASSERT_NO_THROW(decoded = loadImage(kSourceDir + "/textures/" + image));
    const ImageRGBA8 mean = mipChain(decoded).back();
    std::vector<float> line = box1;
    for (int y = 0; y < h; ++y)
      for (int ch = 0; ch < 3; ++ch)
        if (mask[size_t(y) * w + x0]) line[(size_t(y) * w + x0) * 4 + ch] = float(srgbToLinear(mean.pixels[ch] / 255.0));
    SeamStats broken = seamStats(line, mask, w, h, x0);
    printf("[seam] %-12s with a mean-colour seam column: seam %s local %s\n", image, fmt(broken.seam).c_str(),
           fmt(broken.local).c_str());
    EXPECT_GT(broken.seam, 3.0 * broken.local);  // measured: seam 0.243, local 0.0023
  }
}

// How far the pole pixel lies inside its 8 neighbours' range, the worst channel (< 0: outside).
template <typename Pixel>
double poleSlack(Pixel pixel, int w, size_t pole) {
  double slack = 1e30;
  for (int ch = 0; ch < 3; ++ch) {
    double lo = 1e30, hi = -1e30;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        double v = pixel(pole + size_t(dy * w + dx), ch);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    double v = pixel(pole, ch);
    slack = std::min(slack, std::min(v - lo, hi - v));
  }
  return slack;
}

// 3. Looking straight down the sphere's axis at the pole with
// FILTER_BOX: u and its derivatives are undefined there, and near it the footprint covers
// every u. Odd sizes put the centre pixel's ray (1 spp) exactly on the pole; 2x2 samples
// land beside it. No NaN/inf; the pole pixel lies within the range of its 8 neighbours, and
// near the reference's value. The range check needs a reference that passes it: from 9.2
// away uv_grid's white polar band (6 texel rows, 2 degrees) is smaller than a pixel, so there
// the true pole pixel is whiter than all its neighbours; that case checks the value only.
// Measured (slack of the pole in its neighbours' range, < 0 outside; |pole - reference|):
//   earth north, 9.2 and 3 away: 0 (all white), 0 at 1 spp and 2x2
//   earth south, 9.2 away: -0.037 / 0.013 (1 spp), -0.013 / 0.004 (2x2); the reference -0.013
//   earth south, 3 away:   -0.008 / 0.007 (1 spp), 0.009 / 0.023 (2x2); the reference -0.012
//   uv_grid, 1.5 away: 0, 0;  9.2 away: -0.125 / 0 (1 spp), -0.132 / 0.003; reference -0.133
// Before the pole handling (a level from every u at 8 probes) the pole pixel was 0.64 off.
// Limits: slack >= -1e-3 where the reference's is >= 0; |pole - reference| < 0.05.
TEST_F(ImageFilterTest, PoleViewIsFiniteAndSmooth) {
  const int w = 65, h = 49;
  const size_t pole = size_t(h / 2) * w + w / 2;
  struct Case {
    const char* name;
    const char* image;
    const char* eye;
    double fov;
  } cases[] = {{"earth_north_far", "earth.jpg", "(0, 9.2, 0)", 30.0},
               {"earth_south_far", "earth.jpg", "(0, -9.2, 0)", 30.0},
               {"earth_north_near", "earth.jpg", "(0, 3, 0)", 40.0},
               {"earth_south_near", "earth.jpg", "(0, -3, 0)", 40.0},
               {"uv_grid_north_near", "uv_grid.png", "(0, 1.5, 0)", 20.0},
               {"uv_grid_north_far", "uv_grid.png", "(0, 9.2, 0)", 30.0}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Scene scene = sphereScene(c.image, c.eye, "(1, 0, 0)", c.fov);
    ReferenceImage ref = renderReference(scene, w, h, 16);
    double refSlack = poleSlack([&](size_t i, int ch) { return ref.rgb[i * 3 + ch]; }, w, pole);
    for (uint32_t n : {1u, 2u}) {
      std::vector<float> img = render(scene, w, h, OUTPUT_SHADED, n, FILTER_BOX);
      EXPECT_EQ(countNonFinite(img), 0u);
      double slack = poleSlack([&](size_t i, int ch) { return double(img[i * 4 + ch]); }, w, pole);
      double err = 0.0;
      for (int ch = 0; ch < 3; ++ch) err = std::max(err, std::abs(img[pole * 4 + ch] - ref.rgb[pole * 3 + ch]));
      printf("[pole] %-18s %ux%u spp: pole %s inside its neighbours' range (reference %s); "
             "|pole - reference| %s\n",
             c.name, n, n, fmt(slack).c_str(), fmt(refSlack).c_str(), fmt(err).c_str());
      RecordProperty(std::string(c.name) + "_spp" + std::to_string(n * n) + "_slack_refSlack_err",
                     fmt(slack) + " " + fmt(refSlack) + " " + fmt(err));
      if (refSlack >= 0.0) {
        EXPECT_GE(slack, -1e-3) << n << "x" << n << " spp";
      }
      EXPECT_LT(err, 0.05) << n << "x" << n << " spp";
      if (n == 1) {
        writeImage(std::string("pole_") + c.name + "_box1", img, w, h);
        writeImage(std::string("pole_") + c.name + "_ref", referenceToRgba(ref), w, h);
      }
    }
  }
}

// 4. Magnification: every footprint is under a texel, so FILTER_BOX makes the point kernel's
// lookup (level 0, one bilinear tap) and the two images agree to float rounding. Measured:
// identical (max difference 0) in all three; the limit 1e-5 allows other drivers' rounding.
TEST_F(ImageFilterTest, MagnifiedImagesEqualPointSampling) {
  struct Case {
    const char* name;
    Scene scene;
  } cases[] = {
      // The floor from 2 above, looking down: 512 x 256 texels over 40 units, 0.13 texel per pixel.
      {"floor_uv_grid", sceneFromText(flatMaterial("uv_grid.png") +
                                      "camera { eye = (0.3, 2, 0.2); lookat = (0.3, 0, 0.2); up = (0, 0, -1); fov = 40; }\n"
                                      "plane { normal = (0, 1, 0); distance = 0; tex_scale = 40; m; }\n")},
      // Earth from 0.1 above the surface at 30 degrees: about 0.25 texel per pixel.
      {"sphere_earth", sphereScene("earth.jpg", "(0.3, 0.2, 1.05)", "(0, 1, 0)", 30.0)},
      // Earth's u seam (the -x meridian) from 0.05 above the surface: 0.1 texel per pixel.
      {"seam_earth", sphereScene("earth.jpg", "(-1.05, 0.1, 0)", "(0, 1, 0)", 30.0)},
  };
  const int w = 96, h = 72;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<float> point = render(c.scene, w, h, OUTPUT_SHADED, 1, FILTER_POINT);
    EXPECT_EQ(countNonFinite(point), 0u);
    for (uint32_t method : {IMAGE_FILTER_ANISOTROPIC, IMAGE_FILTER_TRILINEAR, IMAGE_FILTER_BILINEAR}) {
      SCOPED_TRACE("image filter " + std::to_string(method));
      imageFilter_ = method;
      std::vector<float> box = render(c.scene, w, h, OUTPUT_SHADED, 1, FILTER_BOX);
      imageFilter_ = IMAGE_FILTER_ANISOTROPIC;
      EXPECT_EQ(countNonFinite(box), 0u);
      double worst = 0.0;
      for (size_t i = 0; i < point.size(); ++i) worst = std::max(worst, double(std::abs(point[i] - box[i])));
      printf("[magnify] %-14s method %u max |box - point| %.3g\n", c.name, method, worst);
      if (method == IMAGE_FILTER_ANISOTROPIC) writeImage(std::string("magnify_") + c.name + "_box1", box, w, h);
      EXPECT_LT(worst, 1e-5);
    }
  }
}

// 5. The other image filter methods (IMAGE_FILTER_*) against the reference, minified, at 1 spp:
// the default's probes, then EWA, trilinear and bilinear without mip levels, each well below the
// next; stochastic filtering, one texel per sample, is noisier than bilinear at 1 spp and
// converges with samples (its expectation is the footprint's box over level 0's bilinear
// texels: the reference's filter). Measured on lavapipe (RMSE; anisotropic, ewa, trilinear,
// bilinear, stochastic 1 and 16 spp):
//   floor_earth          0.0243  0.0572  0.0844  0.2045  0.2208  0.0442
//   far_sphere_uv_grid   0.0196  0.0594  0.0604  0.1099  0.1549  0.0260
// (EWA without its cap of 16 texels a level: 0.0451 and 0.0583.) Limits: each ratio with a
// margin of 10 % or more, but EWA against trilinear on the far sphere, whose footprints are
// nearly round, where the two differ by 2 % (limit: within 5 %); stochastic at 16 spp below 0.3
// of its 1-spp error (noise alone falls to 0.25).
TEST_F(ImageFilterTest, MethodsRankAgainstTheReference) {
  struct Case {
    const char* name;
    Scene scene;
    int w, h, kind;
  } cases[] = {
      {"floor_earth", horizonScene("earth.jpg", 2.0), 128, 96, HIT_PLANE},
      {"far_sphere_uv_grid", sphereScene("uv_grid.png", "(2, 3, 8.5)", "(0, 1, 0)", 30.0), 96, 96, HIT_SPHERE},
  };
  for (Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<bool> mask = interiorMask(c.scene, c.w, c.h, c.kind);
    ReferenceImage ref = renderReference(c.scene, c.w, c.h, 16);
    auto error = [&](uint32_t method, uint32_t side) {
      imageFilter_ = method;
      std::vector<float> img = render(c.scene, c.w, c.h, OUTPUT_SHADED, side, FILTER_BOX);
      imageFilter_ = IMAGE_FILTER_ANISOTROPIC;
      EXPECT_EQ(countNonFinite(img), 0u);
      if (side == 1) writeImage(std::string(c.name) + "_method" + std::to_string(method), img, c.w, c.h);
      return rmseAgainstReference(img.data(), ref, &mask);
    };
    const double anisotropic = error(IMAGE_FILTER_ANISOTROPIC, 1), ewa = error(IMAGE_FILTER_EWA, 1),
                 trilinear = error(IMAGE_FILTER_TRILINEAR, 1), bilinear = error(IMAGE_FILTER_BILINEAR, 1),
                 stochastic1 = error(IMAGE_FILTER_STOCHASTIC, 1), stochastic16 = error(IMAGE_FILTER_STOCHASTIC, 4);
    printf("[methods] %-20s anisotropic %s ewa %s trilinear %s bilinear %s stochastic %s, 16 spp %s\n", c.name,
           fmt(anisotropic).c_str(), fmt(ewa).c_str(), fmt(trilinear).c_str(), fmt(bilinear).c_str(),
           fmt(stochastic1).c_str(), fmt(stochastic16).c_str());
    EXPECT_LT(anisotropic, 0.6 * ewa);
    EXPECT_LT(ewa, 1.05 * trilinear);
    EXPECT_LT(trilinear, 0.6 * bilinear);
    EXPECT_GT(stochastic1, bilinear);
    EXPECT_LT(stochastic16, 0.3 * stochastic1);
  }
}

}  // namespace
