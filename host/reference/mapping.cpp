#include "mapping.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace {
constexpr double kPi = 3.14159265358979323846;

}  // namespace

TexCoordD planeTexCoord(const PlaneFrame& frame, double texScale, glm::dvec3 p) {
  if (!(texScale > 0.0)) throw std::invalid_argument("tex_scale must be > 0");
  const glm::dvec3 origin = frame.distance * frame.normal;  // o' = d n        (6)
  const glm::dvec3 r = p - origin;
  const double up = glm::dot(r, frame.tangent);  // u_p = (p - o') . t     (1)
  const double vp = glm::dot(r, frame.binormal);  // v_p = (p - o') . b
  const double us = up / texScale, vs = vp / texScale;
  TexCoordD tc;
  tc.tile = glm::dvec2(std::floor(us), std::floor(vs));
  tc.uv = glm::dvec2(us - tc.tile.x, vs - tc.tile.y);  // u = u_p/s - floor(u_p/s)  (2)
  tc.solid = p / texScale;
  // The image lookup of the placed mapping (here unplaced).
  TexturePlacement placement;
  placement.scale = texScale;
  const TexCoordD placed = planeTexCoord(frame, placement, p);
  tc.image = placed.image;
  tc.imageTile = placed.imageTile;
  return tc;
}

TexCoordD sphereTexCoord(glm::dvec3 n) {
  const double phi = (n.x == 0.0 && n.z == 0.0) ? 0.0 : std::atan2(n.z, n.x);  // (7)
  const double theta = std::asin(std::fmin(std::fmax(n.y, -1.0), 1.0));
  TexCoordD tc;
  tc.uv = glm::dvec2((phi + kPi) / (2.0 * kPi), (theta + 0.5 * kPi) / kPi);  // (8)
  tc.tile = glm::dvec2(0.0);
  tc.solid = (n + 1.0) * 0.5;  // (9)
  tc.image = glm::dvec2(1.0 - tc.uv.x, 1.0 - tc.uv.y);
  tc.imageTile = -tc.tile;  // 1 - (tile + uv)
  tc.clampV = true;
  return tc;
}

glm::dmat3 placementRotation(glm::dvec3 degrees) {
  const glm::dvec3 a = degrees * (kPi / 180.0);
  const double cx = std::cos(a.x), sx = std::sin(a.x), cy = std::cos(a.y), sy = std::sin(a.y);
  const double cz = std::cos(a.z), sz = std::sin(a.z);
  // glm matrices are built column by column: these are the textbook rows, transposed.
  const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  return rz * ry * rx;
}

glm::dvec3 imageUpAxis(glm::dvec3 n) {
  const glm::dvec3 world = 2.0 * n.y * n.y >= 1.0 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
  return glm::normalize(world - glm::dot(world, n) * n);
}

TexCoordD planeTexCoord(const PlaneFrame& frame, const TexturePlacement& placement, glm::dvec3 p) {
  if (!(placement.scale > 0.0)) throw std::invalid_argument("tex_scale must be > 0");
  const glm::dmat3 inverse = glm::transpose(placementRotation(placement.rotate));
  const glm::dvec3 origin = frame.distance * frame.normal;
  const glm::dvec3 placed = inverse * (p - origin) + origin;  // p'
  const PlaneFrame turned = planeFrame(inverse * frame.normal, frame.distance);
  const glm::dvec3 r = placed - origin;
  const double s = placement.scale;
  const glm::dvec2 unwrapped(glm::dot(r, turned.tangent) / s + placement.offset.x,
                             glm::dot(r, turned.binormal) / s + placement.offset.y);
  TexCoordD tc;
  tc.tile = glm::floor(unwrapped);
  tc.uv = unwrapped - tc.tile;
  tc.solid = placed / s + placement.offset;
  // The image's frame in the plane: top along imageUpAxis, right = up x n (unmirrored seen
  // from the side n points to); rows count downwards.
  const glm::dvec3 up = imageUpAxis(turned.normal);
  const glm::dvec3 right = glm::cross(up, turned.normal);
  const glm::dvec3 w = unwrapped.x * turned.tangent + unwrapped.y * turned.binormal;
  const glm::dvec2 image(glm::dot(w, right), -glm::dot(w, up));
  tc.imageTile = glm::floor(image);
  tc.image = image - tc.imageTile;
  return tc;
}

TexCoordD sphereTexCoord(const TexturePlacement& placement, glm::dvec3 n) {
  if (!(placement.scale > 0.0)) throw std::invalid_argument("tex_scale must be > 0");
  const glm::dvec3 turned = glm::transpose(placementRotation(placement.rotate)) * n;  // n'
  const TexCoordD plain = sphereTexCoord(turned);
  const double s = placement.scale;
  const glm::dvec2 unwrapped = plain.uv / s + glm::dvec2(placement.offset.x, placement.offset.y);
  TexCoordD tc;
  tc.clampV = s == 1.0 && placement.offset.y == 0.0;
  tc.tile = glm::floor(unwrapped);
  if (tc.clampV) tc.tile.y = 0.0;
  tc.uv = unwrapped - tc.tile;
  tc.solid = plain.solid / s + placement.offset;
  tc.image = glm::dvec2(1.0 - tc.uv.x, 1.0 - tc.uv.y);
  tc.imageTile = -tc.tile;  // 1 - (tile + uv)
  return tc;
}
