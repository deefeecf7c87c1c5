// 8-bit images held against each other by the tests and bench/yardstick.cpp: the channel
// differences, a picture of them, resampling; and a frame as a 3-channel float image.
#pragma once

#include "image.h"

#include <cstdint>

// Resamples an sRGB-encoded image (filtering in linear light).
ImageRGBA8 resizeImage(const ImageRGBA8& image, int width, int height);
// The same, into `out` (width x height x 4 bytes).
void resizeImage(const ImageRGBA8& image, int width, int height, uint8_t* out);

struct ImageDiff {
  int maxError = 0;        // largest channel difference, 0..255 (RGB only)
  double meanError = 0.0;  // mean channel difference (RGB only)
  bool sizeMismatch = false;
};
ImageDiff compareImages(const ImageRGBA8& a, const ImageRGBA8& b);
// |a - b| per channel, amplified by `gain`, alpha opaque; for looking at failures.
ImageRGBA8 diffImage(const ImageRGBA8& a, const ImageRGBA8& b, int gain = 8);

// Linear RGBA floats without alpha, a 3-channel FloatImage as readLinearImage gives.
FloatImage rgbFloatImage(const float* rgba, int width, int height);
