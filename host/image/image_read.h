// Image files read as linear float RGB for comparison (`raytex diff`): PNG (8 or 16 bits,
// sRGB decoded to linear), EXR and PFM (linear as stored). Each is checked as image_load.h
// checks PNG and JPEG: format against extension, size, budget, truncation. No Vulkan.
#pragma once

#include "float_image.h"

#include <cstdint>
#include <string>

struct LinearImage {
  FloatImage image;  // 3 channels (RGB), linear
  bool lowDynamicRange = false;  // PNG: values in [0, 1] by construction
};

// Throws ImageInputError naming the path.
LinearImage readLinearImage(const std::string& path, uint64_t maxBytes);
