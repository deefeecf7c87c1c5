// How far apart two images are: measures on linear RGB float images of one size (the colour
// channels compared: the first 3, or the only one). `raytex diff` prints them, and the image
// tests compare through them. No Vulkan.
#pragma once

#include "image_file.h"

#include <vector>

// Side of the square window of the structural similarity.
constexpr int kSsimWindow = 7;

// Square root of the mean squared channel difference, over every pixel or over the pixels
// flagged in `mask` (0 if none are).
double rootMeanSquareError(const FloatImage& a, const FloatImage& b, const std::vector<bool>* mask = nullptr);
// 10 log10(1 / rmse^2) in dB, the peak value being 1; +infinity for rmse 0.
double peakSignalToNoise(double rmse);
// The mean structural similarity (Wang et al. 2004) of two images holding sRGB-encoded values
// in [0, 1], as scikit-image's structural_similarity computes it with its defaults: a
// kSsimWindow x kSsimWindow uniform window, sample covariances (N - 1), K1 = 0.01, K2 = 0.03,
// data range 1, averaged over every window wholly inside the image and over the channels.
// NaN for an image narrower or lower than the window. Computed a row at a time (the window
// sums of the last kSsimWindow rows kept, 280 bytes a column per channel), each channel on a
// thread of its own.
double structuralSimilarity(const FloatImage& aSrgb, const FloatImage& bSrgb);
// The largest absolute channel difference.
double maxChannelDifference(const FloatImage& a, const FloatImage& b);
// The share, 0 to 1, of pixels whose largest channel difference is over `threshold`.
double shareOverThreshold(const FloatImage& a, const FloatImage& b, double threshold);

// How many values of the colour channels are NaN or infinite.
size_t nonFiniteCount(const FloatImage& image);

// Linear RGBA floats (a rendered frame, row 0 at the top) as a 4-channel FloatImage.
FloatImage rgbaFloatImage(const float* rgba, int width, int height);

// Linear values clamped to [0, 1] and sRGB-encoded, in [0, 1] (non-finite values become 0).
FloatImage linearToSrgbImage(const FloatImage& linear);
// Pixels x0 .. x1 - 1 of row y of linearToSrgbImage(linear), their first 3 channels (3 floats
// a pixel into `rgb`), without the copy of the image: the rows flipErrorMap reads.
void linearToSrgbRow(const FloatImage& linear, int y, int x0, int x1, float* rgb);
// When either image is of low dynamic range, clamps both to [0, 1]: an HDR value above 1 and
// the 1 an LDR file stores for it are the same pixel on a display.
void clampForComparison(LinearImage& a, LinearImage& b);

// Every measure of `test` against `reference` (linear), the share counted over `threshold`;
// the SSIM that of linearToSrgbImage of each, encoded a row at a time without the copies.
struct ImageMetrics {
  double rmse = 0.0;
  double psnr = 0.0;  // +infinity when the images are equal
  double ssim = 0.0;  // of the sRGB encodings; NaN for an image smaller than the window
  double maxDifference = 0.0;
  double shareOver = 0.0;
};
ImageMetrics measureImages(const FloatImage& reference, const FloatImage& test, double threshold);
