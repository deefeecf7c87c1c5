// JPEG, read with libjpeg-turbo: the header alone, or the whole image as 8-bit RGBA. The caller
// opens the file (image_file.h checks its name and signature). No Vulkan.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

// Whether the n bytes start with a JPEG's start-of-image marker.
bool isJpeg(const uint8_t* bytes, size_t n);

// Reads the header of `file` (from its start: the markers up to the scan) into width and
// height; with `rgba`, decodes the image into it (width x height x 4 bytes, alpha 255), the
// size then having to be the one given. False with `message` on any error or warning of the
// decoder (a truncated file is only a warning to libjpeg) and for CMYK and YCCK files.
bool decodeJpeg(FILE* file, int* width, int* height, uint8_t* rgba, std::string* message);
