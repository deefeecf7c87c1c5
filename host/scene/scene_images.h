// The image files a scene's materials use, checked from their headers alone before any is
// decoded: each readable as PNG or JPEG and at most kMaxImageFileSide a side, at most
// MAX_IMAGES of them (common.h), and their textures on the GPU within a budget. No Vulkan.
#pragma once

#include "image_file.h"
#include "scene.h"

#include <cstdint>
#include <string>
#include <vector>

// Budget of image texture bytes uploaded, in MiB (--max-image-mib).
constexpr uint32_t kDefaultMaxImageMiB = 512;

struct SceneImage {
  std::string path;  // resolved as the scene gives it (TextureDesc::imagePath)
  FileLoc loc;       // the texture's `file` value
  ImageHeader header;
};

// Bytes of one image's texture on the GPU: its own size, 4 bytes a texel, and its full mip
// chain's levels when `mipmaps`.
uint64_t imageChainBytes(const ImageHeader& header, bool mipmaps);
// Bytes of these images' textures: the sum of their chains.
uint64_t imageUploadBytes(const std::vector<SceneImage>& images, bool mipmaps);

// The image files of `materials` (indices into scene.materials; -1, the default material, and
// non-image textures skipped; each file once), in order of first use, with their headers.
// Throws ImageInputError at the texture's location for a file that cannot be probed, and
// SceneError for the image after the first MAX_IMAGES (before its header is read), and at the first image that brings
// imageUploadBytes over maxImageMiB.
std::vector<SceneImage> probeSceneImages(const Scene& scene, const std::vector<int>& materials, bool mipmaps,
                                         uint32_t maxImageMiB);

// Decodes the image into rgba (its header's size, 4 bytes a texel). Throws ImageInputError at its
// location when the file is corrupt, truncated or changed since it was probed.
void decodeSceneImage(const SceneImage& image, uint8_t* rgba);

// Empty when these images fit a device's maxImageDimension2D; otherwise one line naming the
// image over it. (Their count fits every device: MAX_IMAGES is Vulkan's minimum.)
std::string imagesOverDeviceLimits(const std::vector<SceneImage>& images, uint32_t maxImageDimension2D);
