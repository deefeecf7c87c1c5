#include "tile_lists.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace {

struct TileRect {
  uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // tiles [x0, x1] x [y0, y1]
};

// The tiles a sphere's screen bounds touch: the film positions of its bounding cube's corners,
// its radius grown by 1e-4 of its size and distance and the bounds by a pixel, far beyond the
// float rounding of the kernel's rays and sphere test. All tiles if a corner is not in front.
TileRect tilesOf(const gpu::Frame& f, const gpu::Sphere& s, uint32_t columns, uint32_t rows) {
  const glm::dvec3 forward(f.cameraForward), right(f.cameraRight), up(f.cameraUp);
  const glm::dvec3 c(s.centerRadius);
  const double r = double(s.centerRadius.w) + 1e-4 * (glm::length(c) + double(s.centerRadius.w));
  const TileRect all{0, 0, columns - 1, rows - 1};
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 q = c + r * glm::dvec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    const double z = glm::dot(q, forward);
    if (!(z > 1e-6 * glm::length(q))) return all;
    const double ndcX = glm::dot(q, right) / (glm::dot(right, right) * z);
    const double ndcY = glm::dot(q, up) / (glm::dot(up, up) * z);
    const double x = (ndcX + 1.0) * 0.5 * f.width, y = (1.0 - ndcY) * 0.5 * f.height;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (!(x1 >= -1.0 && y1 >= -1.0 && x0 <= f.width + 1.0 && y0 <= f.height + 1.0)) return {1, 1, 0, 0};  // off screen
  auto tile = [](double v, uint32_t count) {
    return uint32_t(std::clamp(std::floor(v / TILE_SIZE), 0.0, double(count - 1)));
  };
  return {tile(x0 - 1.0, columns), tile(y0 - 1.0, rows), tile(x1 + 1.0, columns), tile(y1 + 1.0, rows)};
}

uint64_t area(const TileRect& t) {
  return t.x1 < t.x0 || t.y1 < t.y0 ? 0 : uint64_t(t.x1 - t.x0 + 1) * (t.y1 - t.y0 + 1);
}

}  // namespace

TileLists buildTileLists(const gpu::Frame& f, const std::vector<gpu::Sphere>& spheres) {
  TileLists lists;
  lists.columns = (f.width + TILE_SIZE - 1) / TILE_SIZE;
  lists.rows = (f.height + TILE_SIZE - 1) / TILE_SIZE;
  const size_t tiles = size_t(lists.columns) * lists.rows;
  std::vector<TileRect> rects(spheres.size());
  uint64_t entries = 0;
  for (size_t i = 0; i < spheres.size(); ++i) {
    rects[i] = tilesOf(f, spheres[i], lists.columns, lists.rows);
    entries += area(rects[i]);
  }
  std::vector<uint32_t> counts(tiles, 0);
  const bool fill = entries <= uint64_t(TILE_FILL_LIMIT) * tiles;
  if (fill)
    for (const TileRect& t : rects)
      for (uint32_t y = t.y0; y <= t.y1 && t.x0 <= t.x1; ++y)
        for (uint32_t x = t.x0; x <= t.x1; ++x) ++counts[size_t(y) * lists.columns + x];
  else
    std::fill(counts.begin(), counts.end(), TILE_USE_TREE);
  lists.ranges.resize(2 * tiles);
  uint32_t next = 0;
  for (size_t t = 0; t < tiles; ++t) {
    const bool tree = counts[t] > TILE_LIST_MAX;
    lists.ranges[2 * t] = next;
    lists.ranges[2 * t + 1] = tree ? TILE_USE_TREE : 0u;
    next += tree ? 0u : counts[t];
  }
  lists.spheres.resize(next);
  for (uint32_t i = 0; fill && i < rects.size(); ++i) {
    const TileRect& t = rects[i];
    for (uint32_t y = t.y0; y <= t.y1 && t.x0 <= t.x1; ++y)
      for (uint32_t x = t.x0; x <= t.x1; ++x) {
        uint32_t* range = &lists.ranges[2 * (size_t(y) * lists.columns + x)];
        if (range[1] != TILE_USE_TREE) lists.spheres[range[0] + range[1]++] = i;
      }
  }
  return lists;
}
