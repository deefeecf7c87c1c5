#include "shadow_lists.h"

#include "gpu_tree.h"
#include "plane_shadow.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace {

// The cone from a light around a sphere A: every segment from a point of A to the light lies
// in it, within `length` of the light, and so in the cylinder of radius `reach` around its
// axis from the apex to that length.
struct Cone {
  glm::dvec3 apex, axis;  // axis: unit
  double sine = 0, cosine = 1, length = 0, reach = 0;
};

// Whether the ball (c, radius) meets the cone: inside it, or nearer its surface than radius
// where the closest point of the surface is not the apex.
bool meetsCone(const Cone& k, const glm::dvec3& c, double radius) {
  const glm::dvec3 v = c - k.apex;
  const double distance = glm::length(v);
  if (distance <= radius) return true;
  if (distance - radius > k.length) return false;
  const double along = glm::dot(v, k.axis), across = glm::length(v - along * k.axis);
  const double outside = across * k.cosine - along * k.sine;  // from the surface, in the plane of axis and v
  return outside <= radius && along * k.cosine + across * k.sine >= 0.0;
}

// Whether the box, grown by the cone's reach, meets the cone's axis (slabs): a box that meets
// the cone does.
bool mayMeetCone(const Cone& k, const gpu::BvhNode& n) {
  double enter = 0.0, leave = k.length;
  for (int a = 0; a < 3; ++a) {
    const double lo = double(n.lo[a]) - k.reach - k.apex[a], hi = double(n.hi[a]) + k.reach - k.apex[a];
    if (k.axis[a] == 0.0) {
      if (lo > 0.0 || hi < 0.0) return false;
      continue;
    }
    const double t0 = lo / k.axis[a], t1 = hi / k.axis[a];
    enter = std::max(enter, std::min(t0, t1)), leave = std::min(leave, std::max(t0, t1));
  }
  return enter <= leave;
}

// The spheres that meet `cone`, walking the tree as the kernel does (nodes skip to `next`).
void spheresInCone(const Cone& cone, const std::vector<gpu::Sphere>& spheres, const std::vector<gpu::BvhNode>& nodes,
                   std::vector<uint32_t>& out) {
  for (uint32_t i = 0; i < nodes.size();) {
    const gpu::BvhNode& n = nodes[i];
    const bool meets = mayMeetCone(cone, n);
    const uint32_t count = treeLeafCount(n), first = treeLeafFirst(n);
    for (uint32_t k = first; meets && k < first + count; ++k) {
      const gpu::Sphere& s = spheres[k];
      if (meetsCone(cone, glm::dvec3(s.centerRadius), paddedRadius(s, cone.apex))) out.push_back(k);
    }
    i = meets && count == 0 ? i + 1 : n.next;
  }
}

// The tiles of B's shadow on a plane (plane_shadow.h), clipped to the view (widened by two
// pixels) and put on screen: every tile where the shadow is unbounded.
class ShadowTiles {
 public:
  ShadowTiles(const gpu::Frame& f, uint32_t columns, uint32_t rows)
      : f_(f), columns_(columns), rows_(rows), view_(viewSides(f)) {}

  TileRect tiles(const gpu::Sphere& b, const gpu::Plane& plane, const glm::dvec3& light) const {
    const PlaneShadow shadow = planeShadow(b, plane, light);
    if (shadow.extent == ShadowExtent::None) return {};
    if (shadow.extent == ShadowExtent::Unbounded) return TileRect{0, 0, columns_ - 1, rows_ - 1};
    if (insideView(shadow.points)) return tilesOfPoints(f_, shadow.points, 8, columns_, rows_);
    const glm::dvec3 n(plane.normalDistance);
    const std::vector<glm::dvec3> clipped = clipToView(hullOnPlane({shadow.points, shadow.points + 8}, n));
    return clipped.empty() ? TileRect{} : tilesOfPoints(f_, clipped.data(), clipped.size(), columns_, rows_);
  }

 private:
  bool insideView(const glm::dvec3 (&points)[8]) const {
    for (const glm::dvec3& p : points)
      for (const glm::dvec3& m : view_.inward)
        if (!(glm::dot(m, p) >= 0.0)) return false;
    return true;
  }

  // The polygon cut to the view's four sides (Sutherland-Hodgman).
  std::vector<glm::dvec3> clipToView(std::vector<glm::dvec3> polygon) const {
    for (const glm::dvec3& m : view_.inward) {
      std::vector<glm::dvec3> kept;
      for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const double dp = glm::dot(m, p), dq = glm::dot(m, q);
        if (dp >= 0.0) kept.push_back(p);
        if ((dp >= 0.0) != (dq >= 0.0)) kept.push_back(p + (dp / (dp - dq)) * (q - p));
      }
      polygon = std::move(kept);
    }
    return polygon;
  }

  const gpu::Frame& f_;
  uint32_t columns_, rows_;
  ViewSides view_;
};

// Shadow entries gathered per (cell, light) key, in counts-then-fill order (as the primary
// lists): those from the planes' shadows.
struct KeyedEntries {
  std::vector<uint32_t> first, entries;
};

// tooMany[l]: light l's lists would hold more than TILE_FILL_LIMIT entries a cell on average
// (spheres above it cast unbounded shadows, say), and its entries are left out.
KeyedEntries planeShadowEntries(const gpu::Frame& f, const std::vector<gpu::Sphere>& spheres,
                                const std::vector<gpu::Plane>& planes, const std::vector<gpu::Light>& lights,
                                const TileLists& lists, std::vector<char>& tooMany) {
  const size_t cells = size_t(lists.shadowColumns) * lists.shadowRows, keys = cells * lights.size();
  const ShadowTiles shadow(f, lists.columns, lists.rows);
  struct Rect {
    uint32_t sphere, light;
    TileRect tiles;  // in cells
  };
  std::vector<Rect> rects;
  std::vector<uint64_t> total(lights.size(), 0);
  for (uint32_t i = 0; i < spheres.size(); ++i)
    for (const gpu::Plane& p : planes)
      for (uint32_t l = 0; l < lights.size(); ++l) {
        const TileRect t = shadow.tiles(spheres[i], p, glm::dvec3(lights[l].position));
        const TileRect c{t.x0 / SHADOW_CELL, t.y0 / SHADOW_CELL, t.x1 / SHADOW_CELL, t.y1 / SHADOW_CELL};
        if (!t.empty()) rects.push_back({i, l, c}), total[l] += c.area();
      }
  tooMany.resize(lights.size());
  for (size_t l = 0; l < lights.size(); ++l) tooMany[l] = total[l] > uint64_t(TILE_FILL_LIMIT) * cells;
  rects.erase(std::remove_if(rects.begin(), rects.end(), [&](const Rect& r) { return tooMany[r.light]; }), rects.end());
  KeyedEntries out;
  out.first.assign(keys + 1, 0);
  auto each = [&](const Rect& r, auto&& visit) {
    for (uint32_t y = r.tiles.y0; y <= r.tiles.y1; ++y)
      for (uint32_t x = r.tiles.x0; x <= r.tiles.x1; ++x)
        visit((size_t(y) * lists.shadowColumns + x) * lights.size() + r.light);
  };
  for (const Rect& r : rects) each(r, [&](size_t key) { ++out.first[key + 1]; });
  for (size_t k = 0; k < keys; ++k) out.first[k + 1] += out.first[k];
  std::vector<uint32_t> next(out.first.begin(), out.first.end() - 1);
  out.entries.resize(out.first[keys]);
  for (const Rect& r : rects) each(r, [&](size_t key) { out.entries[next[key]++] = r.sphere; });
  return out;
}

// Per sphere and light, the spheres that meet the cone from the light around it (found when a
// cell first needs them); TILE_USE_TREE where the light is within the sphere.
class Casters {
 public:
  Casters(const std::vector<gpu::Sphere>& spheres, const std::vector<gpu::Light>& lights,
          const std::vector<gpu::BvhNode>& nodes)
      : spheres_(spheres), lights_(lights), nodes_(nodes), first_(spheres.size() * lights.size(), kUnknown),
        count_(first_.size(), 0) {}

  // Calls visit(b) for each caster b of sphere a for light l; false where the cell must walk
  // the tree.
  template <typename Visit>
  bool each(uint32_t a, uint32_t l, Visit&& visit) {
    const size_t key = size_t(a) * lights_.size() + l;
    if (first_[key] == kUnknown) find(a, l, key);
    if (count_[key] == TILE_USE_TREE) return false;
    for (uint32_t k = first_[key]; k < first_[key] + count_[key]; ++k) visit(entries_[k]);
    return true;
  }

 private:
  static constexpr uint32_t kUnknown = ~0u;

  void find(uint32_t a, uint32_t l, size_t key) {
    const glm::dvec3 light(lights_[l].position), c(spheres_[a].centerRadius);
    const double r = paddedRadius(spheres_[a], light), distance = glm::length(c - light);
    first_[key] = uint32_t(entries_.size());
    if (!(distance > r)) {
      count_[key] = TILE_USE_TREE;
      return;
    }
    const double sine = r / distance, cosine = std::sqrt(1.0 - sine * sine);
    const Cone cone{light, (c - light) / distance, sine, cosine, distance + r, (distance + r) * sine / cosine};
    spheresInCone(cone, spheres_, nodes_, entries_);
    count_[key] = uint32_t(entries_.size()) - first_[key];
  }

  const std::vector<gpu::Sphere>& spheres_;
  const std::vector<gpu::Light>& lights_;
  const std::vector<gpu::BvhNode>& nodes_;
  std::vector<uint32_t> first_, count_, entries_;
};

}  // namespace

bool shadowListsFit(size_t lights, size_t planes) {
  return lights > 0 && lights <= SHADOW_LIST_MAX_LIGHTS && planes <= SHADOW_LIST_MAX_PLANES;
}

void appendShadowLists(const gpu::Frame& f, const std::vector<gpu::Sphere>& spheres,
                       const std::vector<gpu::Plane>& planes, const std::vector<gpu::Light>& lights,
                       const std::vector<gpu::BvhNode>& nodes, TileLists& lists) {
  lists.shadowColumns = (lists.columns + SHADOW_CELL - 1) / SHADOW_CELL;
  lists.shadowRows = (lists.rows + SHADOW_CELL - 1) / SHADOW_CELL;
  const size_t cells = size_t(lists.shadowColumns) * lists.shadowRows;
  lists.shadowRanges = uint32_t(lists.ranges.size());
  lists.ranges.resize(lists.ranges.size() + 2 * cells * lights.size(), 0);
  uint32_t* ranges = lists.ranges.data() + lists.shadowRanges;
  std::vector<char> tooMany;
  const KeyedEntries fromPlanes = planeShadowEntries(f, spheres, planes, lights, lists, tooMany);
  Casters casters(spheres, lights, nodes);
  std::vector<uint32_t> seen(spheres.size(), ~0u);  // the key a sphere was last listed for
  std::vector<uint32_t>& out = lists.spheres;
  out.reserve(out.size() + fromPlanes.entries.size() + cells);
  for (uint32_t cell = 0; cell < cells; ++cell) {
    const uint32_t cx = cell % lists.shadowColumns * SHADOW_CELL, cy = cell / lists.shadowColumns * SHADOW_CELL;
    for (uint32_t l = 0; l < lights.size(); ++l) {
      const uint32_t key = uint32_t(cell * lights.size() + l), start = uint32_t(out.size());
      ranges[2 * key] = start;
      auto add = [&](uint32_t i) {
        if (seen[i] != key) seen[i] = key, out.push_back(i);
      };
      for (uint32_t k = fromPlanes.first[key]; k < fromPlanes.first[key + 1]; ++k) add(fromPlanes.entries[k]);
      // A list stops growing once it is over SHADOW_LIST_MAX: the cell walks the tree anyway.
      auto fits = [&] { return out.size() - start <= SHADOW_LIST_MAX; };
      bool listed = !tooMany[l] && fits();
      for (uint32_t y = cy; listed && y < std::min(cy + SHADOW_CELL, lists.rows); ++y)
        for (uint32_t x = cx; listed && x < std::min(cx + SHADOW_CELL, lists.columns); ++x) {
          const uint32_t* tile = &lists.ranges[2 * (size_t(y) * lists.columns + x)];
          const uint32_t first = tile[0], count = tile[1];
          listed = count != TILE_USE_TREE;
          for (uint32_t i = first; listed && i < first + count; ++i) listed = casters.each(out[i], l, add) && fits();
        }
      ranges[2 * key + 1] = listed ? uint32_t(out.size()) - start : TILE_USE_TREE;
      if (!listed) out.resize(start);
    }
  }
}
