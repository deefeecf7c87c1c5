#include "ray_count.h"

#include "parallel.h"
#include "reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

RayCount countRays(const Scene& scene, uint32_t width, uint32_t height, uint32_t samplesPerSide) {
  const int n = int(std::max(samplesPerSide, 1u));
  RayCount count;
  count.primary = uint64_t(width) * height * n * n;
  if (width == 0 || height == 0) return count;
  const ReferenceCamera camera = referenceCamera(scene.camera, int(width), int(height));
  const glm::dvec3 eye = scene.camera.eye;
  const SphereBvh bvh = buildSphereBvh(scene.spheres);
  std::vector<uint64_t> rowShadow(height, 0);
  forEachRowInParallel(int(height), 0, [&](int y) {
    uint64_t shadow = 0;
    for (int x = 0; x < int(width); ++x) {
      for (int sy = 0; sy < n; ++sy) {
        for (int sx = 0; sx < n; ++sx) {
          const glm::dvec3 dir =
              referenceRayDirection(camera, x, y, referenceSampleOffset(sx, n), referenceSampleOffset(sy, n));
          const ReferenceHit hit = referenceClosestHit(scene, eye, dir, false, &bvh);
          if (hit.kind == 0) continue;
          const glm::dvec3 normal = glm::dot(hit.n, dir) > 0.0 ? -hit.n : hit.n;  // facing the viewer
          for (const Light& light : scene.lights) {
            const glm::dvec3 toLight = light.position - hit.p;
            if (glm::dot(toLight, toLight) > 0.0 && glm::dot(normal, toLight) > 0.0) ++shadow;
          }
        }
      }
    }
    rowShadow[y] = shadow;
  });
  count.shadow = std::accumulate(rowShadow.begin(), rowShadow.end(), uint64_t(0));
  return count;
}
