#include "texture.h"

#include "noise.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace {
struct KindName {
  TextureKind kind;
  const char* name;
};
const KindName kKindNames[] = {
    {TextureKind::Image, "image"},           {TextureKind::Checker, "checker"},
    {TextureKind::SolidChecker, "solid_checker"}, {TextureKind::Noise, "noise"},
    {TextureKind::Marble, "marble"},         {TextureKind::Wood, "wood"},
    {TextureKind::Turbulence, "turbulence"}, {TextureKind::DTurbulence, "dturbulence"},
};
}  // namespace

const char* textureKindName(TextureKind kind) {
  for (const KindName& k : kKindNames)
    if (k.kind == kind) return k.name;
  return "none";
}

bool textureKindFromName(const std::string& name, TextureKind* kind) {
  for (const KindName& k : kKindNames) {
    if (name == k.name) {
      *kind = k.kind;
      return true;
    }
  }
  return false;
}

bool isSolidTexture(TextureKind kind) {
  return kind != TextureKind::None && kind != TextureKind::Image && kind != TextureKind::Checker;
}

TextureDesc defaultTexture(TextureKind kind) {
  TextureDesc t;
  t.kind = kind;
  switch (kind) {
    case TextureKind::None:
    case TextureKind::Image:
      break;
    case TextureKind::Checker:
      t.color1 = glm::vec3(0.9f);
      t.color2 = glm::vec3(0.1f);
      t.squares = 2.0f;
      break;
    case TextureKind::SolidChecker:
      t.color1 = glm::vec3(0.9f, 0.1f, 0.1f);
      t.color2 = glm::vec3(0.9f);
      t.squares = 4.0f;
      break;
    case TextureKind::Noise:
      t.color1 = glm::vec3(0.05f, 0.1f, 0.4f);
      t.color2 = glm::vec3(0.9f, 0.9f, 0.8f);
      t.scale = 8.0f;
      break;
    case TextureKind::Marble:
      t.color1 = glm::vec3(0.9f, 0.88f, 0.85f);
      t.color2 = glm::vec3(0.15f, 0.12f, 0.2f);
      t.scale = 4.0f;
      t.strength = 6.0f;
      t.octaves = 6;
      break;
    case TextureKind::Wood:
      t.color1 = glm::vec3(0.75f, 0.5f, 0.25f);
      t.color2 = glm::vec3(0.35f, 0.18f, 0.07f);
      t.scale = 8.0f;
      t.strength = 0.25f;
      t.octaves = 4;
      break;
    case TextureKind::Turbulence:
    case TextureKind::DTurbulence:
      t.color1 = glm::vec3(0.95f, 0.85f, 0.6f);
      t.color2 = glm::vec3(0.3f, 0.1f, 0.05f);
      t.scale = 6.0f;
      // Derivative turbulence damps octaves on slopes, so it needs more gain for the same contrast.
      t.strength = kind == TextureKind::DTurbulence ? 2.5f : 1.25f;
      t.octaves = 6;
      break;
  }
  return t;
}

namespace {
constexpr double kPi = 3.14159265358979323846;

double clamp01(double t) { return std::fmin(std::fmax(t, 0.0), 1.0); }

// 0 for an even integer, 1 for an odd one (x - 2 floor(x/2), as GLSL mod(x, 2.0)).
double parity(double x) { return x - 2.0 * std::floor(x * 0.5); }
}  // namespace

double textureBlendReference(const TextureDesc& texture, const TexCoordD& tc) {
  const double scale = texture.scale, strength = texture.strength;
  const int octaves = texture.octaves;
  const glm::dvec3 q = tc.solid * scale;
  switch (texture.kind) {
    case TextureKind::Checker: {
      const double sq = std::fmax(std::floor(double(texture.squares) + 0.5), 1.0);
      const glm::dvec2 cell = glm::floor(tc.uv * sq);
      return parity(cell.x + cell.y + sq * (tc.tile.x + tc.tile.y));
    }
    case TextureKind::SolidChecker: {
      const glm::dvec3 cell = glm::floor(tc.solid * double(texture.squares));
      return parity(cell.x + cell.y + cell.z);
    }
    case TextureKind::Noise:
      return clamp01(0.5 + 0.5 * perlinNoise(q));
    case TextureKind::Marble: {
      // Veins along the planes x + y = const, displaced by turbulence; cubing the
      // [0,1] sine profile keeps the color2 veins thin.
      const double s = 0.5 + 0.5 * std::sin(kPi * (q.x + q.y) + strength * turbulence(q, octaves));
      return clamp01(s * s * s);
    }
    case TextureKind::Wood: {
      // Rings around the y axis through the solid cube's centre, `scale` rings per
      // unit radius, wobbled by turbulence stretched 4x along the axis (grain).
      const double r = glm::length(glm::dvec2(tc.solid.x - 0.5, tc.solid.z - 0.5));
      const glm::dvec3 w(q.x, 0.25 * q.y, q.z);
      const double rings = scale * r + strength * turbulence(w, octaves);
      const double f = rings - std::floor(rings);
      return clamp01(f * f);
    }
    case TextureKind::Turbulence:
      return clamp01(strength * turbulence(q, octaves));
    case TextureKind::DTurbulence:
      return clamp01(strength * dturbulence(q, octaves));
    case TextureKind::None:
    case TextureKind::Image:
      break;
  }
  throw std::invalid_argument(std::string("textureBlendReference: no CPU reference for texture kind ") +
                              textureKindName(texture.kind));
}

glm::dvec3 textureColorReference(const TextureDesc& texture, const TexCoordD& tc) {
  const double t = textureBlendReference(texture, tc);
  const glm::dvec3 c1(texture.color1), c2(texture.color2);
  return c1 + (c2 - c1) * t;
}
