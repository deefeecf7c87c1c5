// The sRGB transfer function, and linear float pixels encoded to 8 and 16-bit sRGB. No Vulkan.
#pragma once

#include "image.h"

#include <cstddef>
#include <cstdint>

double srgbToLinear(double encoded);  // encoded in [0, 1]
double linearToSrgb(double linear);   // linear in [0, 1]

// srgbToLinear of the 256 8-bit codes.
const float* srgbDecodeTable();

// Linear float RGBA (row 0 at the top) to sRGB-encoded RGBA8, clamped to [0, 1].
// Non-finite channels become 0 and are counted in *nonFinite when given.
ImageRGBA8 encodeSrgb(const float* rgba, int width, int height, size_t* nonFinite = nullptr);

// sRGB-encoded 16-bit value of a linear value, clamped to [0, 1] (not finite: 0).
uint16_t srgb16(float linear);
