// LDR-FLIP: the difference a viewer sees when flipping between a reference and a test image,
// per pixel in [0, 1], from Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images" (HPG 2020). Inputs are sRGB-encoded
// values in [0, 1] seen at kFlipPixelsPerDegree pixels per degree of visual angle.
//
// Colour pipeline: sRGB -> linear RGB -> YCxCz, each channel filtered by its contrast
// sensitivity function (the paper's Gaussians), back to linear RGB clamped to the sRGB gamut,
// to L*a*b* with the Hunt adjustment, the HyAB distance, redistributed to [0, 1].
// Feature pipeline: edges and points of the achromatic channel, from Gaussian first and second
// derivatives whose width scales with the pixels per degree. The two combine as
// error = colourError ^ (1 - featureError). Every stage is a function so its tests can check
// it. Filters repeat the edge pixels outside the image. No Vulkan.
#pragma once

#include "image.h"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <vector>

// A 0.7 m wide monitor of 3840 pixels viewed from 0.7 m: the paper's default observer.
constexpr double kFlipPixelsPerDegree = 67.0;

// The paper's constants: the exponent on the HyAB distance (qc), the breakpoint as a share of
// the largest distance (pc) and its error (pt), and the exponent on the feature error (qf).
constexpr double kFlipColorExponent = 0.7;
constexpr double kFlipColorBreak = 0.4;
constexpr double kFlipColorBreakError = 0.95;
constexpr double kFlipFeatureExponent = 0.5;
constexpr double kFlipFeatureWidthDegrees = 0.082;  // w: the width of the features detected

// --- colour conversions (CIE XYZ relative to the sRGB white, Y of white = 1) ---
glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb);
glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz);
glm::dvec3 xyzToYcxcz(const glm::dvec3& xyz);  // linearised L*a*b*: (116 Y - 16, 500 (X - Y), 200 (Y - Z))
glm::dvec3 ycxczToXyz(const glm::dvec3& ycxcz);
glm::dvec3 xyzToLab(const glm::dvec3& xyz);  // CIE 1976 L*a*b*
// a* and b* scaled by L* / 100: colours close to black differ less (the Hunt effect).
glm::dvec3 huntAdjust(const glm::dvec3& lab);
// |L1 - L2| + the Euclidean distance of (a, b).
double hyab(const glm::dvec3& lab1, const glm::dvec3& lab2);
// The largest colour distance, between Hunt-adjusted green and blue, raised to qc.
double flipMaxColorDistance();
// The HyAB distance of two Hunt-adjusted colours to the colour error in [0, 1]: raised to qc,
// then linear up to pc * cmax (error pt there) and linear from there to cmax (error 1).
double redistributeColorError(double hyabDistance);
// error = colourError ^ (1 - featureError).
double combineFlipErrors(double colorError, double featureError);

// --- filters ---
// One dimension of a separable kernel: weights at offsets -radius..radius.
struct Kernel1D {
  int radius = 0;
  std::vector<double> weights;  // 2 * radius + 1
};
// A 2D kernel as a sum of outer products: weight(dx, dy) = sum over terms of x[dx] * y[dy].
struct KernelTerm {
  Kernel1D x, y;
};
using SeparableKernel = std::vector<KernelTerm>;

enum class CsfChannel { Achromatic, RedGreen, BlueYellow };

// Radius of the contrast sensitivity filters: 3 standard deviations of the widest Gaussian
// (b = 0.04, blue-yellow) in pixels, rounded up; 10 at 67 pixels per degree.
int csfRadius(double pixelsPerDegree);
// The spatial filter of a channel's contrast sensitivity function: the sum of the paper's
// Gaussians a sqrt(pi / b) exp(-pi^2 r^2 / b), r in degrees, normalised to sum 1.
SeparableKernel csfKernel(CsfChannel channel, double pixelsPerDegree);

enum class FeatureKind { Edge, Point };
// Radius of the feature filters: 3 standard deviations, sigma = w / 2 * ppd, rounded up.
int featureRadius(double pixelsPerDegree);
// The x-direction detector (its transpose detects in y): the first (edge) or second (point)
// derivative in x of a Gaussian of sigma w / 2 * ppd pixels, its positive weights normalised to
// sum 1 and its negative weights to sum -1.
KernelTerm featureKernel(FeatureKind kind, double pixelsPerDegree);

// A w x h plane (row 0 first) filtered with `kernel`, repeating the edge pixels: what every
// filter of the stages computes.
std::vector<double> filterPlane(const std::vector<double>& plane, int w, int h, const SeparableKernel& kernel);

// --- the pipelines ---
// sRGB values in [0, 1] (the first 3 channels) to YCxCz, 3 channels.
FloatImage srgbToYcxcz(const FloatImage& srgb);
// Each channel filtered by its contrast sensitivity function (Y, Cx, Cz).
FloatImage filterCsf(const FloatImage& ycxcz, double pixelsPerDegree);
// Filtered YCxCz to linear RGB clamped to [0, 1], then to Hunt-adjusted L*a*b*.
FloatImage ycxczToHuntLab(const FloatImage& ycxcz);
// Per pixel colour error in [0, 1] of two Hunt-adjusted L*a*b* images, 1 channel.
FloatImage colorErrorMap(const FloatImage& referenceLab, const FloatImage& testLab);

// Edge and point strength of the achromatic channel ((Y + 16) / 116 of YCxCz, in [0, 1]):
// the length of the (x, y) detector responses, 1 channel each.
struct FeatureMaps {
  FloatImage edges, points;
};
FeatureMaps detectFeatures(const FloatImage& ycxcz, double pixelsPerDegree);
// Per pixel (max(|edge difference|, |point difference|) / sqrt(2)) ^ qf, 1 channel.
FloatImage featureErrorMap(const FeatureMaps& reference, const FeatureMaps& test);

// The FLIP error per pixel in [0, 1], 1 channel, of two sRGB images of the same size (values
// in [0, 1], 3 or 4 channels, the first 3 compared). Identical images give 0 everywhere.
FloatImage flipErrorMap(const FloatImage& referenceSrgb, const FloatImage& testSrgb);
// Writes pixels x0 .. x1 - 1 of row y (0 at the top) of an image's sRGB values, 3 floats a
// pixel, into `rgb`.
using SrgbRows = std::function<void(int y, int x0, int x1, float* rgb)>;
// Columns of the tiles flipErrorMap computes one at a time.
constexpr int kFlipTileColumns = 1024;
// The same error map, of two width x height images given a row at a time: the stages run row by
// row over tiles of `tileColumns` columns and `bands` bands of rows (0: one per processor
// thread, each of at least 512 rows), the tiles on the processor threads (so the rows are read
// from several threads at once). A tile reads its pixels and the 10 around it (the widest
// filter's radius) once each, and holds about 2.6 kB a column of filtered rows: 2.7 MB for
// 1024 columns, whatever the image's size. The map is the whole-image stages' to the bit, in
// any tiles: every value comes from the same operations in the same order.
FloatImage flipErrorMap(int width, int height, const SrgbRows& reference, const SrgbRows& test, int bands = 0,
                        int tileColumns = kFlipTileColumns);
// The mean of an error map (0 for an empty one).
double flipMean(const FloatImage& error);

// The colour of `error` (clamped to [0, 1]) in the heat map: dark purple through magenta and
// orange to pale yellow, its lightness rising throughout.
std::array<uint8_t, 3> heatmapColor(double error);
// The error map in heatmapColor, opaque.
ImageRGBA8 flipHeatmap(const FloatImage& error);
