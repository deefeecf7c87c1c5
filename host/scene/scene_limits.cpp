#include "scene_limits.h"

#include "common.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

uint32_t sphereTreeFor(size_t spheres) {
  if (spheres < SPHERE_TREE_MIN_SPHERES) return SPHERE_TREE_NONE;
  return spheres <= MAX_UNIFORM_SPHERES ? SPHERE_TREE_UNIFORM : SPHERE_TREE_STORAGE;
}

namespace {

// The first object that uses `material`.
FileLoc firstUse(const Scene& scene, int material) {
  for (const Sphere& o : scene.spheres)
    if (o.material == material) return o.loc;
  for (const Plane& o : scene.planes)
    if (o.material == material) return o.loc;
  return scene.path.empty() ? FileLoc{} : FileLoc{scene.path, 1, 1};
}

template <typename Items>
void checkCount(const Items& items, size_t max, const char* what) {
  if (items.size() > max) checkRoomFor(max, max, what, items[max].loc);
}

}  // namespace

void checkRoomFor(size_t count, size_t max, const char* what, const FileLoc& loc) {
  if (count < max) return;
  const std::string singular(what, strlen(what) - 1);  // "spheres" -> "sphere"
  throw SceneError(loc, singular + " " + std::to_string(count + 1) + " is over the limit: raytex renders at most " +
                            std::to_string(max) + " " + what);
}

void checkSceneLimits(const Scene& scene) {
  checkCount(scene.spheres, MAX_SPHERES, "spheres");
  checkCount(scene.planes, MAX_PLANES, "planes");
  checkCount(scene.lights, MAX_LIGHTS, "lights");
  std::vector<int> used = usedMaterials(scene);
  if (used.size() > MAX_MATERIALS)
    throw SceneError(firstUse(scene, used[MAX_MATERIALS]),
                     "the scene's objects use more than " + std::to_string(MAX_MATERIALS) + " materials");
}

size_t loopTestedObjects(const Scene& scene) {
  const bool tree = sphereTreeFor(scene.spheres.size()) != SPHERE_TREE_NONE;
  return scene.planes.size() + (tree ? 0 : scene.spheres.size());
}

void checkLoopLimit(const Scene& scene, uint32_t traces) {
  if (withinLoopLimit(scene, traces)) return;
  const size_t objects = loopTestedObjects(scene);
  const uint64_t iterations = traces * loopIterationsPerSample(scene);
  // With n lights, traces ((n + 1) (objects + 3) + reserve) passes the limit from
  // n = (limit / traces - reserve) / (objects + 3) on.
  const uint64_t reserve = LOOP_PASSES_PER_SAMPLE + 1, perLight = objects + 3;
  const uint64_t share = kMaxLoopIterations / traces;
  const size_t over = size_t(share > reserve ? (share - reserve) / perLight : 0);
  const size_t first = std::min(std::max<size_t>(over, 1), scene.lights.size()) - 1;
  const std::string sum = "(lights + 1) x (objects + 3) + " + std::to_string(reserve);
  throw SceneError(scene.lights[first].loc,
                   "the scene has " + std::to_string(scene.lights.size()) + " lights and " + std::to_string(objects) +
                       " objects every ray tests: " + (traces > 1 ? std::to_string(traces) + " x (" + sum + ")" : sum) +
                       " = " + std::to_string(iterations) + " loop passes per " +
                       (traces > 1 ? "edge pixel of the coverage filter" : "sample") + ", more than the " +
                       std::to_string(kMaxLoopIterations) + " the lavapipe driver runs");
}
