// The PNG writer of image_writer.h: the image held whole (8-bit sRGB as encodeSrgb makes it,
// or 16-bit sRGB), encoded at the end, with the metadata as text chunks. No Vulkan.
#pragma once

#include "band_sink.h"
#include "image_writer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

// A PNG of `depth` bits (8 or 16) a channel at `path`, RGB from the first `channels` (1 to 3)
// components of the band's plane `source` (Band::plane): one channel is grey, two leave blue 0.
std::unique_ptr<BandSink> makePngSink(const std::string& path, int width, int height, int depth, int source,
                                      int channels, const Metadata& metadata);
