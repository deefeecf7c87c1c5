// The PNG writer of image_output.h: the image held whole (8-bit sRGB as encodeSrgb makes it,
// or 16-bit sRGB), encoded at the end, with the metadata as text chunks. No Vulkan.
#pragma once

#include "band_sink.h"
#include "image_output.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

// A PNG of `depth` bits (8 or 16) a channel at `path`, RGB from the first `channels` (1 to 3)
// components of the band's plane `source` (Band::plane): one channel is grey, two leave blue 0.
std::unique_ptr<BandSink> makePngSink(const std::string& path, int width, int height, int depth, int source,
                                      int channels, const Metadata& metadata);

// An RGB PNG of 16 bits a channel: `rgb` holds width x height x 3 values, row 0 at the top.
std::vector<uint8_t> encodePng16(const std::vector<uint16_t>& rgb, int width, int height);

// `png` with one tEXt chunk per key and value (iTXt, UTF-8, for a value that is not ASCII)
// after its IHDR chunk.
void insertPngText(std::vector<uint8_t>& png, const Metadata& metadata);

// sRGB-encoded 16-bit value of a linear value, clamped to [0, 1] (not finite: 0).
uint16_t srgb16(float linear);
