#include "shadow_grid.h"

#include "plane_shadow.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace {

// A shadow in the plane's coordinates (along its tangent t and binormal b, as the kernel takes
// them: dot products with the camera-relative point): the hull of its corners, counter-clockwise
// in (t, b), and their bounds.
struct Shadow {
  uint32_t sphere;
  uint32_t corners;  // of the hull
  glm::dvec2 hull[8];
  glm::dvec2 lo, hi;
};

// The plane's axes and every sphere's shadow on it.
struct PlaneShadows {
  glm::dvec3 t, b;
  std::vector<Shadow> shadows;
};

// Cells a side of a grid, at most.
constexpr uint32_t kMaxGridSide = 4096;

// The shadows on plane p, in `out`; false where the light is not above p or a shadow is unbounded.
bool shadowsOnPlane(const std::vector<gpu::Sphere>& spheres, const gpu::Plane& p, const glm::dvec3& light,
                    PlaneShadows& out) {
  if (!(glm::dot(glm::dvec3(p.normalDistance), light) - p.normalDistance.w > 0.0)) return false;
  out.t = glm::dvec3(p.tangentScale), out.b = glm::dvec3(p.binormal);
  out.shadows.clear();
  std::vector<glm::dvec2> uv(8);
  for (uint32_t i = 0; i < spheres.size(); ++i) {
    const PlaneShadow s = planeShadow(spheres[i], p, light);
    if (s.extent == ShadowExtent::Unbounded) return false;
    if (s.extent == ShadowExtent::None) continue;
    for (int k = 0; k < 8; ++k) uv[k] = glm::dvec2(glm::dot(s.points[k], out.t), glm::dot(s.points[k], out.b));
    Shadow shadow{i, 0, {}, glm::dvec2(INFINITY), glm::dvec2(-INFINITY)};
    for (size_t k : hullOrder(uv)) {
      shadow.hull[shadow.corners++] = uv[k];
      shadow.lo = glm::min(shadow.lo, uv[k]), shadow.hi = glm::max(shadow.hi, uv[k]);
    }
    out.shadows.push_back(shadow);
  }
  return true;
}

// A grid over the shadows' bounds, about a cell a shadow, with a free cell on every side.
struct Grid {
  glm::dvec2 corner;
  double cell = 1.0;
  uint32_t columns = 0, rows = 0;
};

Grid gridOver(const std::vector<Shadow>& shadows) {
  Grid g;
  if (shadows.empty()) return g;
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  for (const Shadow& s : shadows) lo = glm::min(lo, s.lo), hi = glm::max(hi, s.hi);
  const glm::dvec2 size = glm::max(hi - lo, glm::dvec2(1e-9 * (glm::length(lo) + glm::length(hi))));
  const double limit = kMaxGridSide;
  g.cell = std::max({std::sqrt(size.x * size.y / double(shadows.size())), size.x / (limit - 2), size.y / (limit - 2)});
  g.corner = lo - g.cell;
  g.columns = uint32_t(std::ceil(size.x / g.cell)) + 2;
  g.rows = uint32_t(std::ceil(size.y / g.cell)) + 2;
  return g;
}

// The range of u where the convex polygon meets the band of v in [v0, v1]: the ends of its edges
// clipped to the band; empty (lo > hi) where it misses the band.
glm::dvec2 spanInBand(const Shadow& s, double v0, double v1) {
  glm::dvec2 span(INFINITY, -INFINITY);
  for (uint32_t i = 0; i < s.corners; ++i) {
    const glm::dvec2 a = s.hull[i], b = s.hull[(i + 1) % s.corners];
    const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
    if (hi < v0 || lo > v1) continue;
    for (const double v : {std::clamp(a.y, v0, v1), std::clamp(b.y, v0, v1)}) {
      const double u = a.y == b.y ? a.x : a.x + (b.x - a.x) * ((v - a.y) / (b.y - a.y));
      span = glm::dvec2(std::min(span.x, u), std::max(span.y, u));
    }
    if (a.y == b.y) span = glm::dvec2(std::min({span.x, a.x, b.x}), std::max({span.y, a.x, b.x}));
  }
  return span;
}

// Calls visit(cell) for each grid cell the shadow may cover: the cells its hull meets, row by
// row, each cell grown by `margin` (the kernel's rounding of the point it looks up).
template <typename Visit>
void eachCell(const Grid& g, const Shadow& s, double margin, Visit&& visit) {
  const double last = kMaxGridSide - 1;
  const auto index = [&](double x) { return uint32_t(std::clamp(std::floor(x / g.cell), 0.0, last)); };
  const glm::dvec2 lo = s.lo - g.corner - margin, hi = s.hi - g.corner + margin;
  const uint32_t y1 = std::min(index(hi.y), g.rows - 1);
  for (uint32_t y = index(lo.y); y <= y1; ++y) {
    const double v0 = g.corner.y + g.cell * y - margin;
    glm::dvec2 span = s.corners < 3 ? glm::dvec2(s.lo.x, s.hi.x) : spanInBand(s, v0, v0 + g.cell + 2.0 * margin);
    if (span.x > span.y) continue;
    const uint32_t x1 = std::min(index(span.y - g.corner.x + margin), g.columns - 1);
    for (uint32_t x = index(span.x - g.corner.x - margin); x <= x1; ++x) visit(size_t(y) * g.columns + x);
  }
}

// One light's grid over plane `plane`: its cell ranges appended to lists.ranges and its entries
// to lists.spheres; rows TILE_USE_TREE (nothing appended) where the shadows would cover too
// many cells.
gpu::ShadowGrid appendGrid(const PlaneShadows& ps, uint32_t plane, const glm::dvec3& light, size_t sphereCount,
                           TileLists& lists) {
  const Grid g = gridOver(ps.shadows);
  const size_t cells = size_t(g.columns) * g.rows;
  // The kernel's point on the plane is off by a few float steps of the scene's size.
  const double margin = 1e-5 * (glm::length(light) + g.cell * (g.columns + g.rows) + glm::length(g.corner));
  const uint64_t limit = uint64_t(TILE_FILL_LIMIT) * std::max<size_t>(sphereCount, 1);
  std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (cell, sphere)
  for (const Shadow& s : ps.shadows) {
    eachCell(g, s, margin, [&](size_t c) { pairs.emplace_back(uint32_t(c), s.sphere); });
    if (pairs.size() > limit) return noShadowGrid();
  }
  std::vector<uint32_t> first(cells + 1, 0);
  for (const auto& [c, sphere] : pairs) ++first[c + 1];
  for (size_t c = 0; c < cells; ++c) first[c + 1] += first[c];
  const gpu::ShadowGrid grid{plane, g.columns, g.rows, uint32_t(lists.ranges.size()),
                             glm::vec4(float(g.corner.x), float(g.corner.y), float(1.0 / g.cell), 0.0f)};
  const uint32_t base = uint32_t(lists.spheres.size());
  for (size_t c = 0; c < cells; ++c) {
    lists.ranges.push_back(base + first[c]);
    lists.ranges.push_back(first[c + 1] - first[c]);
  }
  lists.spheres.resize(base + first[cells]);
  for (const auto& [c, sphere] : pairs) lists.spheres[base + first[c]++] = sphere;
  return grid;
}

// Whether some cell's list for light l is long (its rays would walk the tree).
bool someListIsLong(const TileLists& lists, size_t lights, size_t l) {
  const size_t cells = size_t(lists.shadowColumns) * lists.shadowRows;
  for (size_t c = 0; c < cells; ++c)
    if (lists.ranges[lists.shadowRanges + 2 * (c * lights + l) + 1] == TILE_USE_TREE) return true;
  return false;
}

}  // namespace

void appendShadowGrids(const std::vector<gpu::Sphere>& spheres, const std::vector<gpu::Plane>& planes,
                       const std::vector<gpu::Light>& lights, TileLists& lists) {
  lists.shadowGrids.assign(lights.size(), noShadowGrid());
  for (size_t l = 0; l < lights.size(); ++l) {
    if (!someListIsLong(lists, lights.size(), l)) continue;
    const glm::dvec3 light(lights[l].position);
    PlaneShadows ps;
    for (uint32_t p = 0; p < planes.size() && lists.shadowGrids[l].rows == TILE_USE_TREE; ++p)
      if (shadowsOnPlane(spheres, planes[p], light, ps))
        lists.shadowGrids[l] = appendGrid(ps, p, light, spheres.size(), lists);
  }
}
