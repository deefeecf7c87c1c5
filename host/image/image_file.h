// Image files raytex reads: PNG (png_file.h) and JPEG (jpeg_file.h), named by their extension (.png,
// .jpg, .jpeg, any case) and checked against their content. Textures decode to 8-bit sRGB RGBA
// (probeImage, decodeImage, loadImage); `raytex diff` reads them as linear float RGB
// (readSrgbImage; EXR and PFM come from float_file.h). A header probe reads the size without
// decoding, so that callers can refuse an image before allocating for it. Corrupt or truncated
// files are refused, never decoded in part. No Vulkan.
#pragma once

#include "error.h"
#include "image.h"

#include <cstdint>
#include <string>

enum class ImageFormat { Png, Jpeg };

struct ImageHeader {
  int width = 0;
  int height = 0;
  ImageFormat format = ImageFormat::Png;
  int depth = 8;  // bits a channel as stored: 1 to 16 for a PNG, 8 for a JPEG
};

// Reads the file's signature and header only: its format (which must match its extension),
// width and height. Throws ImageInputError (naming the path) for a file that is missing, not a
// regular file, of another format, or whose header is malformed or over kMaxImageFileSide.
ImageHeader probeImage(const std::string& path);

// Decodes the whole file into `rgba` (width x height x 4 bytes, row 0 at the top, sRGB as
// stored), which must hold exactly header.width x header.height texels: the pixels go
// straight into the caller's buffer. Probes the file again and refuses it if its header no
// longer matches. Throws ImageInputError on any error or warning of the decoder.
void decodeImage(const std::string& path, const ImageHeader& header, uint8_t* rgba);

// probeImage, then decodeImage into the image's pixels. Throws ImageInputError.
ImageRGBA8 loadImage(const std::string& path);

struct LinearImage {
  FloatImage image;  // 3 channels (RGB), linear
  bool lowDynamicRange = false;  // PNG, JPEG: values in [0, 1] by construction
};

// A PNG (16 bits at full precision) or JPEG as linear float RGB, alpha dropped, refused before
// decoding when its floats would take more than maxBytes. Throws ImageInputError naming the path.
LinearImage readSrgbImage(const std::string& path, uint64_t maxBytes);
