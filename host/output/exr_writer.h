// The EXR writer of image_writer.h (OpenEXR): a scanline file, ZIP, INCREASING_Y, whose rows
// are handed to OpenEXR as their band comes (a band that comes early is held until its turn:
// top first suits it). Channels R, G, B and A = 1, float or half (a finite value beyond the
// half range is written as +-65504, the largest half, and counted: BandSink::clamped()); each
// pass a layer of "<name>.<letter>" channels and "<name>.A" (coverage); the metadata as string
// attributes.
// A regular file is written in place through its temporary; an output that cannot seek gets
// the file encoded in memory and written through at the end, as OpenEXR goes back to the start
// of the file to write its table of row offsets. OpenEXR runs without threads (its global
// thread count is 0), so that the same input gives the same bytes. No Vulkan.
#pragma once

#include "band_sink.h"
#include "image_writer.h"

#include <memory>

std::unique_ptr<BandSink> makeExrSink(const OutputSpec& spec);
