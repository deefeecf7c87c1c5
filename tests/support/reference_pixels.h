// Per-pixel truths from the CPU double reference (host/reference/reference.h), to hold a kernel image
// against: the closest hit through each pixel, the pixels wholly on an object, and how far a
// kernel texture coordinate lies from the reference's.
#pragma once

#include "reference.h"
#include "scene.h"

#include <algorithm>
#include <cmath>
#include <vector>

// The reference's closest hit through every pixel centre, row 0 at the top.
inline std::vector<ReferenceHit> referenceHits(const Scene& scene, int w, int h) {
  std::vector<ReferenceHit> out;
  out.reserve(size_t(w) * h);
  const glm::dvec3 eye(scene.camera.eye);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      out.push_back(referenceClosestHit(scene, eye, referenceRayDirection(scene.camera, w, h, x, y)));
  return out;
}

// Pixels whose centre and four corners all hit what `keep` accepts (no silhouette pixels).
template <typename Keep>
std::vector<bool> interiorMask(const Scene& scene, int w, int h, Keep keep) {
  std::vector<bool> mask(size_t(w) * h, false);
  const glm::dvec3 eye(scene.camera.eye);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool inside = keep(referenceClosestHit(scene, eye, referenceRayDirection(scene.camera, w, h, x, y)));
      for (double dy : {-0.5, 0.5})
        for (double dx : {-0.5, 0.5})
          inside = inside && keep(referenceClosestHit(scene, eye, referenceRayDirection(scene.camera, w, h, x, y, dx, dy)));
      mask[size_t(y) * w + x] = inside;
    }
  return mask;
}

// Pixels whose centre and four corners all hit an object of kind `kind` (HIT_*).
inline std::vector<bool> interiorMask(const Scene& scene, int w, int h, int kind) {
  return interiorMask(scene, w, h, [kind](const ReferenceHit& hit) { return hit.kind == kind; });
}

// Distance between a kernel coordinate and the reference value in [0, 1]. Only where the
// reference lies within float rounding of a tile border (0 or 1) may the kernel land on the
// other side of it, so only there does the distance wrap. (A plain modulo-1 distance would
// hide u = -0.3 for 0.7: the int-truncation bug.)
inline double coordinateDistance(double gpu, double ref) {
  double d = std::abs(gpu - ref);
  if (std::min(ref, 1.0 - ref) < 1e-4) d = std::min(d, std::abs(1.0 - d));
  return d;
}
