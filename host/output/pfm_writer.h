// The PFM writer of image_writer.h: "PF" (RGB) or "Pf" (grey), little-endian floats, rows
// bottom up. A regular file gets each band at its place as it comes; an output that cannot
// seek gets rows appended bottom first, a band that comes early held until its turn. No Vulkan.
#pragma once

#include "band_sink.h"

#include <memory>
#include <string>

// A PFM at `path` of the first `channels` (1 to 3) components of the band's plane `source`
// (Band::plane): one channel is "Pf", two or three "PF" (two: the third 0).
std::unique_ptr<BandSink> makePfmSink(const std::string& path, int width, int height, int source, int channels);
