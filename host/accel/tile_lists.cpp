#include "tile_lists.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

ViewSides viewSides(const gpu::Frame& f) {
  const glm::dvec3 forward(f.cameraForward), right(f.cameraRight), up(f.cameraUp);
  const double px = 1.0 + 4.0 / f.width, py = 1.0 + 4.0 / f.height;
  const glm::dvec3 r = right / glm::dot(right, right), u = up / glm::dot(up, up);
  return {{px * forward - r, px * forward + r, py * forward - u, py * forward + u}};
}

void boundingCubeCorners(const glm::dvec3& c, double r, glm::dvec3 (&corners)[8]) {
  for (int k = 0; k < 8; ++k) corners[k] = c + r * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
}

TileRect tilesOfPoints(const gpu::Frame& f, const glm::dvec3* points, size_t count, uint32_t columns, uint32_t rows) {
  const glm::dvec3 forward(f.cameraForward), right(f.cameraRight), up(f.cameraUp);
  const TileRect all{0, 0, columns - 1, rows - 1};
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (size_t i = 0; i < count; ++i) {
    const glm::dvec3 q = points[i];
    const double z = glm::dot(q, forward);
    if (!(z > 1e-6 * glm::length(q))) return all;
    const double ndcX = glm::dot(q, right) / (glm::dot(right, right) * z);
    const double ndcY = glm::dot(q, up) / (glm::dot(up, up) * z);
    const double x = (ndcX + 1.0) * 0.5 * f.width, y = (1.0 - ndcY) * 0.5 * f.height;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (!(x1 >= -1.0 && y1 >= -1.0 && x0 <= f.width + 1.0 && y0 <= f.height + 1.0)) return {};  // off screen
  auto tile = [](double v, uint32_t n) { return uint32_t(std::clamp(std::floor(v / TILE_SIZE), 0.0, double(n - 1))); };
  return {tile(x0 - 1.0, columns), tile(y0 - 1.0, rows), tile(x1 + 1.0, columns), tile(y1 + 1.0, rows)};
}

namespace {

// The tiles a sphere's screen bounds touch: the film positions of its bounding cube's corners,
// its radius grown by 1e-4 of its size and distance and the bounds by a pixel, far beyond the
// float rounding of the kernel's rays and sphere test. None if it lies outside the view, all
// tiles if it is in the view and a corner is not in front.
TileRect tilesOf(const gpu::Frame& f, const ViewSides& view, const gpu::Sphere& s, uint32_t columns, uint32_t rows) {
  const glm::dvec3 c(s.centerRadius);
  const double r = double(s.centerRadius.w) + 1e-4 * (glm::length(c) + double(s.centerRadius.w));
  for (const glm::dvec3& side : view.inward)
    if (glm::dot(side, c) < -r * glm::length(side)) return {};
  glm::dvec3 corners[8];
  boundingCubeCorners(c, r, corners);
  return tilesOfPoints(f, corners, 8, columns, rows);
}

}  // namespace

std::vector<uint32_t> nearestFirst(const std::vector<gpu::Sphere>& spheres) {
  std::vector<double> nearest(spheres.size());
  std::vector<uint32_t> order(spheres.size());
  for (uint32_t i = 0; i < spheres.size(); ++i) {
    nearest[i] = glm::length(glm::dvec3(spheres[i].centerRadius)) - double(spheres[i].centerRadius.w);
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return nearest[a] < nearest[b]; });
  return order;
}

TileLists buildTileLists(const gpu::Frame& f, const std::vector<gpu::Sphere>& spheres) {
  TileLists lists;
  lists.columns = (f.width + TILE_SIZE - 1) / TILE_SIZE;
  lists.rows = (f.height + TILE_SIZE - 1) / TILE_SIZE;
  const size_t tiles = size_t(lists.columns) * lists.rows;
  std::vector<TileRect> rects(spheres.size());
  uint64_t entries = 0;
  const ViewSides view = viewSides(f);
  for (size_t i = 0; i < spheres.size(); ++i) {
    rects[i] = tilesOf(f, view, spheres[i], lists.columns, lists.rows);
    entries += rects[i].area();
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
  for (uint32_t i : fill ? nearestFirst(spheres) : std::vector<uint32_t>{}) {
    const TileRect& t = rects[i];
    for (uint32_t y = t.y0; y <= t.y1 && t.x0 <= t.x1; ++y)
      for (uint32_t x = t.x0; x <= t.x1; ++x) {
        uint32_t* range = &lists.ranges[2 * (size_t(y) * lists.columns + x)];
        if (range[1] != TILE_USE_TREE) lists.spheres[range[0] + range[1]++] = i;
      }
  }
  return lists;
}
