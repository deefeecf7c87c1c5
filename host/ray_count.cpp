#include "ray_count.h"

#include "reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace {

// Shadow rays of the rows first, first + step, ...
uint64_t countShadowRays(const Scene& scene, const ReferenceCamera& camera, uint32_t n, uint32_t first,
                         uint32_t step) {
  const glm::dvec3 eye = scene.camera.eye;
  uint64_t shadow = 0;
  for (uint32_t y = first; y < uint32_t(camera.height); y += step) {
    for (uint32_t x = 0; x < uint32_t(camera.width); ++x) {
      for (uint32_t k = 0; k < n * n; ++k) {
        const double dx = (double(k % n) + 0.5) / n - 0.5, dy = (double(k / n) + 0.5) / n - 0.5;
        const glm::dvec3 dir = referenceRayDirection(camera, int(x), int(y), dx, dy);
        const ReferenceHit hit = referenceClosestHit(scene, eye, dir, false);
        if (hit.kind == 0) continue;
        const glm::dvec3 normal = glm::dot(hit.n, dir) > 0.0 ? -hit.n : hit.n;  // facing the viewer
        for (const Light& light : scene.lights) {
          const glm::dvec3 toLight = light.position - hit.p;
          if (glm::dot(toLight, toLight) > 0.0 && glm::dot(normal, toLight) > 0.0) ++shadow;
        }
      }
    }
  }
  return shadow;
}

}  // namespace

RayCount countRays(const Scene& scene, uint32_t width, uint32_t height, uint32_t samplesPerSide) {
  const uint32_t n = std::max(samplesPerSide, 1u);
  RayCount count;
  count.primary = uint64_t(width) * height * n * n;
  if (width == 0 || height == 0) return count;
  const ReferenceCamera camera = referenceCamera(scene.camera, int(width), int(height));
  // Interleaved rows, so every thread gets a share of the objects.
  const uint32_t threads = std::min({std::max(std::thread::hardware_concurrency(), 1u), 16u, height});
  std::vector<uint64_t> shadow(threads, 0);
  std::vector<std::exception_ptr> errors(threads);  // rethrown here: a throw in a thread would end the process
  auto countShare = [&](uint32_t t) {
    try {
      shadow[t] = countShadowRays(scene, camera, n, t, threads);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  uint32_t started = 1;  // share 0 is this thread's
  for (; started < threads; ++started) {
    try {
      workers.emplace_back(countShare, started);
    } catch (const std::system_error&) {
      break;  // no more threads: this one counts the rest
    }
  }
  countShare(0);
  for (uint32_t t = started; t < threads; ++t) countShare(t);
  for (std::thread& worker : workers) worker.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  for (uint64_t s : shadow) count.shadow += s;
  return count;
}
