// Images in memory: 8-bit sRGB RGBA (textures as decoded, the PNGs raytex writes) and linear
// float (what EXR and PFM files hold, what a pass is, what `raytex diff` compares). No Vulkan.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

// Largest width or height of an image file raytex decodes.
constexpr int kMaxImageFileSide = 16384;

struct ImageRGBA8 {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;  // row 0 at the top, 4 bytes per pixel
};

struct FloatImage {
  int width = 0;
  int height = 0;
  int channels = 4;           // floats per pixel: 1, 3 or 4 (RGBA)
  std::vector<float> pixels;  // row 0 at the top, `channels` floats per pixel
  float at(int x, int y, int c) const { return pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c)]; }
};
