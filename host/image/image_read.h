// PNG (8 or 16 bits) and JPEG files read as linear float RGB for comparison (`raytex diff`,
// through readLinearImage in host/output/output_formats.h, which reads EXR and PFM with
// float_input.h): sRGB decoded to linear, checked as image_load.h checks them: format against
// extension, size, budget, truncation. No Vulkan.
#pragma once

#include "float_image.h"

#include <cstdint>
#include <string>

struct LinearImage {
  FloatImage image;  // 3 channels (RGB), linear
  bool lowDynamicRange = false;  // PNG, JPEG: values in [0, 1] by construction
};

// A PNG (16 bits at full precision) or JPEG, alpha dropped. Throws ImageInputError naming the path.
LinearImage readSrgbImage(const std::string& path, uint64_t maxBytes);
