#include "scene_images.h"

#include "common.h"
#include "image_file.h"
#include "mip_chain.h"

#include <algorithm>
#include <cstdio>

namespace {

std::string sizeText(const ImageHeader& h) { return std::to_string(h.width) + "x" + std::to_string(h.height); }

std::string mibText(uint64_t bytes) {
  char text[32];
  snprintf(text, sizeof(text), "%.1f", double(bytes) / (1024.0 * 1024.0));
  return text;
}

void checkBudget(const std::vector<SceneImage>& images, bool mipmaps, uint32_t maxImageMiB) {
  const uint64_t bytes = imageUploadBytes(images, mipmaps);
  if (bytes <= uint64_t(maxImageMiB) * 1024 * 1024) return;
  const SceneImage& last = images.back();
  throw SceneError(last.loc, "image '" + last.path + "' (" + sizeText(last.header) + ") brings the scene's images to " +
                                 mibText(bytes) + " MiB on the GPU (" + std::to_string(images.size()) +
                                 (images.size() == 1 ? " image at its own size" : " images at their own sizes") +
                                 (mipmaps ? ", 4 bytes a texel, with mip levels" : ", 4 bytes a texel") +
                                 "), over the budget of " + std::to_string(maxImageMiB) +
                                 " MiB (--max-image-mib N raises it)");
}

}  // namespace

uint64_t imageChainBytes(const ImageHeader& header, bool mipmaps) {
  const int levels = mipmaps ? mipLevelCount(header.width, header.height) : 1;
  uint64_t bytes = 0;
  for (int l = 0; l < levels; ++l)
    bytes += uint64_t(std::max(1, header.width >> l)) * uint64_t(std::max(1, header.height >> l)) * 4;
  return bytes;
}

uint64_t imageUploadBytes(const std::vector<SceneImage>& images, bool mipmaps) {
  uint64_t bytes = 0;
  for (const SceneImage& i : images) bytes += imageChainBytes(i.header, mipmaps);
  return bytes;
}

std::vector<SceneImage> probeSceneImages(const Scene& scene, const std::vector<int>& materials, bool mipmaps,
                                         uint32_t maxImageMiB) {
  std::vector<SceneImage> images;
  for (int m : materials) {
    if (m < 0) continue;
    const TextureDesc& t = scene.materials[size_t(m)].texture;
    if (t.kind != TextureKind::Image) continue;
    auto same = [&](const SceneImage& i) { return i.path == t.imagePath; };
    if (std::find_if(images.begin(), images.end(), same) != images.end()) continue;
    if (images.size() == MAX_IMAGES)
      throw SceneError(t.loc, "image '" + t.imagePath + "' is the scene's " + std::to_string(MAX_IMAGES + 1) +
                                  "th image file; raytex renders at most " + std::to_string(MAX_IMAGES));
    SceneImage image{t.imagePath, t.loc, {}};
    try {
      image.header = probeImage(image.path);
    } catch (const ImageInputError& e) {
      throw ImageInputError(t.loc, e.what());
    }
    images.push_back(std::move(image));
    checkBudget(images, mipmaps, maxImageMiB);
  }
  return images;
}

void decodeSceneImage(const SceneImage& image, uint8_t* rgba) {
  try {
    decodeImage(image.path, image.header, rgba);
  } catch (const ImageInputError& e) {
    throw ImageInputError(image.loc, e.what());
  }
}

std::string imagesOverDeviceLimits(const std::vector<SceneImage>& images, uint32_t maxImageDimension2D) {
  for (const SceneImage& i : images)
    if (uint32_t(i.header.width) > maxImageDimension2D || uint32_t(i.header.height) > maxImageDimension2D)
      return "image '" + i.path + "' is " + sizeText(i.header) + ": the device's images are at most " +
             std::to_string(maxImageDimension2D) + " a side (maxImageDimension2D)";
  return "";
}
