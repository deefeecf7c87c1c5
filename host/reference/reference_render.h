// The float64 reference renderer: the same scene model as the GPU kernel, written
// independently (reference.cpp intersection, mapping.cpp, noise.cpp, texture.cpp and the
// Phong shading here), with N x N stratified supersampling and a box pixel filter.
// Slow by design: the ground truth for tests and accuracy charts.
#pragma once

#include "srgb.h"
#include "mapping.h"
#include "reference.h"
#include "scene.h"
#include "scene_images.h"

#include <glm/vec3.hpp>

#include <map>
#include <string>
#include <vector>

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<double> rgb;  // linear, 3 per pixel, row 0 at the top
  size_t nonFinite = 0;     // non-finite channel values (written as they are)
};

// Decoded image textures of the materials objects use, by resolved path. Throws ImageInputError
// at the texture's `file` location when one cannot be loaded, or SceneError, before decoding any, when
// they are more than MAX_IMAGES files or their headers show more than maxImageMiB for the
// GPU's textures (as a point-filtered GPU render counts it: probeSceneImages), so that both
// renderers accept the same scenes.
std::map<std::string, ImageRGBA8> loadReferenceImages(const Scene& scene,
                                                      uint32_t maxImageMiB = kDefaultMaxImageMiB);

// Bilinear sample in linear light at tc.image = (column, row) as fractions of the image, row 0
// at the top (docs/textures.md, "Image orientation"), columns repeating; rows repeating too, or
// clamped to the texel centres where tc.clampV (spheres). wrap = clamp: at the unwrapped lookup
// imageTile + image clamped to [0, 1], both axes clamped to the texel centres (CLAMP_TO_EDGE:
// the image once, its edge texels beyond).
glm::dvec3 sampleImageReference(const ImageRGBA8& image, const TexCoordD& tc, ImageWrap wrap = ImageWrap::Repeat);

// The texture colour at the hit (k_d untextured): the reference's diffuse coefficient, point
// sampled.
glm::dvec3 referenceAlbedo(const std::map<std::string, ImageRGBA8>& images, const Material& m, const ReferenceHit& hit);

// Renders with samplesPerSide^2 samples per pixel on `threads` threads (0: all cores).
// maxImageMiB: as loadReferenceImages.
ReferenceImage renderReference(const Scene& scene, int width, int height, int samplesPerSide,
                               int threads = 0, uint32_t maxImageMiB = kDefaultMaxImageMiB);

// Linear RGBA floats (alpha 1) for encodeSrgb.
std::vector<float> referenceToRgba(const ReferenceImage& image);
