// PNG, read and written with libpng's decoder and zlib's deflate: the one PNG codec of raytex
// (textures and `raytex diff` read through it, `raytex render` writes through it). The caller
// opens the file (image_file.h checks its name and signature). No Vulkan.
#pragma once

#include "image.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

// Whether the n bytes start with the PNG signature.
bool isPng(const uint8_t* bytes, size_t n);

// The IHDR chunk of a PNG `file` positioned just after its signature: size and bit depth a
// channel (1 to 16). False with `error` for a header that is missing, malformed or empty.
bool readPngHeader(FILE* file, const std::string& path, int* width, int* height, int* depth, std::string* error);

// Decodes the whole `file` (from its start) of width x height texels into `out`: with depth 8,
// RGBA8 as stored (any bit depth and colour type; a palette index past the palette is an error);
// with depth 16, 16-bit RGB in host byte order (the file must store 16 bits), alpha dropped.
// False with `message` on any error of the decoder, or a size other than the one given.
bool decodePng(FILE* file, int width, int height, int depth, void* out, std::string* message);

// The PNG file's bytes, RGB: `samples` holds width x height x 3 values of `depth` bits (8:
// bytes; 16: uint16_t in host byte order), row 0 at the top; the sub filter on every row and
// deflate at level 1. Empty if encoding failed.
std::vector<uint8_t> encodePng(const void* samples, int width, int height, int depth);
// An 8-bit RGBA image as an 8-bit RGB PNG (alpha dropped: the images raytex writes are opaque).
std::vector<uint8_t> encodePng(const ImageRGBA8& image);

// Key and value pairs written as text chunks.
using PngText = std::vector<std::pair<std::string, std::string>>;

// `png` with one tEXt chunk per key and value (iTXt, UTF-8, for a value that is not ASCII)
// after its IHDR chunk.
void insertPngText(std::vector<uint8_t>& png, const PngText& text);
