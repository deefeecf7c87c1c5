// Test images for the output writers (image_writer.h): a colour and passes as the renderer
// hands them over (vec4s, rows top first), written band by band in a chosen order.
#pragma once

#include "image_writer.h"

#include <string>
#include <vector>

struct BandImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;                 // 4 floats a pixel
  std::vector<std::vector<float>> passes;  // 4 floats a pixel each: values, then coverage
};

// Distinct, exactly known values in every pixel and channel: colours above 1 and below 0,
// alpha 0.5 (EXR writes 1 instead); pass coverage 0 or 1.
BandImage bandImage(int width, int height, const std::vector<Pass>& passes);

enum class BandOrder { OneBand, TopFirst, BottomFirst, Shuffled };

// Writes `image` to `output` in bands of `rows` rows (the last one shorter), in `order`.
void writeBands(ImageWriter& output, const BandImage& image, int rows, BandOrder order);

// An OutputSpec for `image` at `path`.
OutputSpec bandSpec(const std::string& path, OutputFormat format, const BandImage& image,
                    const std::vector<Pass>& passes);

// Opens, writes in bands and finishes; returns ImageWriter::nonFinite().
size_t writeBandImage(const OutputSpec& spec, const BandImage& image, int rows, BandOrder order);
