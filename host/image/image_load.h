// Image files read from disk: PNG (libpng) and JPEG (libjpeg-turbo) only, named by their
// extension (.png, .jpg, .jpeg, any case) and checked against their content. A header probe
// reads the size without decoding, so that callers can refuse an image before allocating for
// it. Corrupt or truncated files are refused, never decoded in part. No Vulkan.
#pragma once

#include "error.h"
#include "image_io.h"

#include <cstdint>
#include <string>

// Largest width or height of an image file raytex decodes.
constexpr int kMaxImageFileSide = 16384;

enum class ImageFormat { Png, Jpeg };

struct ImageHeader {
  int width = 0;
  int height = 0;
  ImageFormat format = ImageFormat::Png;
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
