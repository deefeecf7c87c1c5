// Mip chains of 8-bit sRGB images, averaged in linear light. No Vulkan.
#pragma once

#include "image.h"

#include <cstdint>
#include <vector>

// Number of levels of a full mip chain: floor(log2(max(width, height))) + 1.
int mipLevelCount(int width, int height);

// The full mip chain of an sRGB-encoded RGBA8 image, level 0 (the image itself) first, the 1x1
// level last. Level i is max(1, w >> i) x max(1, h >> i) (Vulkan's rule). Each texel is the
// exact area average of the previous level's texels under it, in linear light (RGB decoded
// from sRGB, alpha linear), re-encoded to sRGB: an odd size still averages every texel, with
// fractional weights, so the texel grid keeps covering [0,1]^2 exactly. Levels are computed
// from the previous level's unrounded linear values (no 8-bit rounding builds up).
std::vector<ImageRGBA8> mipChain(const ImageRGBA8& image);
std::vector<ImageRGBA8> mipChain(ImageRGBA8&& image);  // moves the image into level 0
// The levels above level 0 of the chain of a width x height image (4 bytes a texel), written
// to out[0] (level 1), out[1] (level 2), ..., each max(1, width >> l) x max(1, height >> l) x 4
// bytes. Made row by row: besides the output, it holds a few rows of
// floats per level, never a whole level.
void writeMipLevels(const uint8_t* pixels, int width, int height, uint8_t* const* out);
