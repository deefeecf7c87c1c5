#include "tile_kernels.h"

#include "gpu_scene.h"
#include "texture_kinds.h"

#include <algorithm>
#include <map>

static_assert(TILE_SIZE == WORKGROUP_X && TILE_SIZE == WORKGROUP_Y, "a tile kernel's workgroup renders one tile");

namespace {

// Lavapipe, 2 threads: the default scene's 1080p frame, 25.4 ms at 195 x86 instructions per
// pixel (docs/performance.md, "Tile kernels").
constexpr double kMsPerInstruction = 25.4 / (1920.0 * 1080.0 * 195.0);
// Creating and compiling one more pipeline (measured there too).
constexpr double kPipelineMs = 110.0;
// x86 instructions per pixel of a sphere's latitude and longitude (as TextureKindInfo::kernelCost).
constexpr double kSphereLatLongCost = 18.0;

uint32_t kindBit(const gpu::Material& m) { return 1u << m.textureKind; }

// The tiles' distinct kind sets and how many tiles have each.
std::map<TextureKinds, uint64_t> kindCounts(const std::vector<TextureKinds>& tiles) {
  std::map<TextureKinds, uint64_t> counts;
  for (const TextureKinds& t : tiles) ++counts[t];
  return counts;
}

// Each set's kindsCost.
std::vector<double> familyCosts(const std::vector<TextureKinds>& family) {
  std::vector<double> costs;
  for (const TextureKinds& kinds : family) costs.push_back(kindsCost(kinds));
  return costs;
}

// The cheapest set of `family` (whose costs are `costs`) that covers `kinds` (family[0] covers all).
size_t cheapestCover(const std::vector<TextureKinds>& family, const std::vector<double>& costs,
                     const TextureKinds& kinds) {
  size_t best = 0;
  for (size_t k = 1; k < family.size(); ++k)
    if (family[k].covers(kinds) && costs[k] < costs[best]) best = k;
  return best;
}

// Estimated instructions per pixel over all tiles when each runs its cheapest cover.
double familyCost(const std::vector<TextureKinds>& family, const std::map<TextureKinds, uint64_t>& counts) {
  const std::vector<double> costs = familyCosts(family);
  double cost = 0.0;
  for (const auto& [kinds, count] : counts) cost += double(count) * costs[cheapestCover(family, costs, kinds)];
  return cost;
}

}  // namespace

std::vector<TextureKinds> tileKinds(const GpuScene& g) {
  const TileLists& lists = g.tiles;
  const size_t tiles = size_t(lists.columns) * lists.rows;
  TextureKinds planes, spheres;
  for (const gpu::Plane& p : g.planes) planes.plane |= kindBit(g.materials[p.material]);
  for (const gpu::Sphere& s : g.spheres) spheres.sphere |= kindBit(g.materials[s.material]);
  std::vector<TextureKinds> kinds(tiles, planes);
  for (size_t t = 0; t < tiles && lists.ranges.size() >= 2 * tiles; ++t) {
    const uint32_t first = lists.ranges[2 * t], count = lists.ranges[2 * t + 1];
    if (count == TILE_USE_TREE) {
      kinds[t].sphere = spheres.sphere;
      continue;
    }
    for (uint32_t i = first; i < first + count; ++i) kinds[t].sphere |= kindBit(g.materials[g.spheres[lists.spheres[i]].material]);
  }
  return kinds;
}

double kindsCost(const TextureKinds& kinds) {
  // A sphere's latitude and longitude, for its 2D kinds (trace.comp.glsl, SPHERE_LAT_LONG).
  double cost = kinds.sphere & TEX_2D_KINDS ? kSphereLatLongCost : 0.0;
  const uint32_t all = kinds.sphere | kinds.plane;
  for (const TextureKindInfo& info : textureKinds())
    if (all & (1u << uint32_t(info.kind))) cost += info.kernelCost;
  return cost;
}

std::vector<TextureKinds> chooseTileKernels(const std::vector<TextureKinds>& tiles, const TextureKinds& all) {
  const std::map<TextureKinds, uint64_t> counts = kindCounts(tiles);
  std::vector<TextureKinds> family{all};
  double cost = familyCost(family, counts);
  while (family.size() < MAX_TILE_KERNELS) {
    std::vector<TextureKinds> best;
    for (const auto& entry : counts) {
      std::vector<TextureKinds> trial = family;
      trial.push_back(entry.first);
      const double c = familyCost(trial, counts);
      if (c < cost) cost = c, best = trial;
    }
    if (best.empty()) break;
    family = best;
  }
  return family;
}

std::vector<TextureKinds> sphereFreeTileKernels(const TextureKinds& all) {
  return {all, TextureKinds{0, all.plane}};
}

bool sphereFreeTilesSave(const TextureKinds& all) {
  return kindsCost(all) - kindsCost({0, all.plane}) > kTileOrderCost;
}

TilePlan assignTiles(const std::vector<TextureKinds>& family, const std::vector<TextureKinds>& tiles, uint32_t columns) {
  TilePlan plan;
  plan.kernels.resize(family.size());
  for (size_t k = 0; k < family.size(); ++k) plan.kernels[k].kinds = family[k];
  const std::vector<double> costs = familyCosts(family);
  for (uint32_t t = 0; t < tiles.size(); ++t) {
    const size_t k = cheapestCover(family, costs, tiles[t]);
    plan.kernels[k].tiles.push_back(t % columns | (t / columns) << 16);
    plan.savedInstructions += double(TILE_SIZE * TILE_SIZE) * (costs[0] - costs[k] - kTileOrderCost);
  }
  plan.kernels.erase(std::remove_if(plan.kernels.begin(), plan.kernels.end(),
                                    [](const TileKernel& k) { return k.tiles.empty(); }),
                     plan.kernels.end());
  return plan;
}

KernelKey tileKernelKey(KernelKey key, const TextureKinds& kinds) {
  key.tileOrder = 1;
  key.shape.sphereKinds = kinds.sphere;
  key.shape.planeKinds = kinds.plane;
  return key;
}

TilePlan planTileKernels(const GpuScene& g, const TextureKinds& all) {
  const std::vector<TextureKinds> tiles = tileKinds(g);
  return assignTiles(chooseTileKernels(tiles, all), tiles, g.tiles.columns);
}

bool tileKernelsPay(const TilePlan& plan, double samples) {
  if (!(plan.savedInstructions > 0)) return false;
  return plan.savedInstructions * samples * kMsPerInstruction > double(plan.kernels.size() - 1) * kPipelineMs;
}
