// Float image files read whole, linear, for comparison (`raytex diff`, through readLinearImage,
// host/output/output_formats.h): EXR (OpenEXR) and PFM. Each is checked as image_file.h checks
// PNG and JPEG, before any pixel is allocated: a regular file, the format's magic number, a size
// of 1 to kMaxImageFileSide a side, width x height x 12 bytes within the caller's budget; then
// data that is all there and decodes. Values that are not finite are kept (the caller decides).
// No Vulkan.
#pragma once

#include "image.h"

#include <cstdint>
#include <string>

// The R, G and B channels of a scanline or tiled EXR (its first level), as stored; without
// them, luminance Y with chroma RY and BY (sampled 2x2, as OpenEXR's RgbaOutputFile writes
// them with WRITE_YCA) converted to RGB by OpenEXR's RgbaInputFile, in half precision; or Y
// alone as grey. Channels of other layers ("depth.Z") are not read. 3 channels, row 0 at the top
// of the data window. Beside the image (12 bytes a pixel) only rows are held: OpenEXR's chunk
// buffers and, for luminance and chroma, about 34 rows of 8 bytes a pixel (RgbaInputFile's
// filter and one row read). Throws ImageInputError ("path: message").
FloatImage readExr(const std::string& path, uint64_t maxBytes);

// A PFM: "PF" (RGB) or "Pf" (grey, given as RGB), either byte order (the sign of its scale),
// its exact length. 3 channels, row 0 at the top. Throws ImageInputError ("path: message").
FloatImage readPfm(const std::string& path, uint64_t maxBytes);
