#include "texture.h"

#include "noise.h"
#include "texture_kinds.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <stdexcept>

namespace {

double clamp01(double t) { return std::fmin(std::fmax(t, 0.0), 1.0); }

// 0 for an even integer, 1 for an odd one (x - 2 floor(x/2), as GLSL mod(x, 2.0)).
double parity(double x) { return x - 2.0 * std::floor(x * 0.5); }

// One function per kind, each the formula of docs/textures.md in double precision.
double checkerReference(const TextureDesc& t, const TexCoordD& tc) {
  const double sq = std::fmax(std::floor(double(t.squares) + 0.5), 1.0);
  const glm::dvec2 cell = glm::floor(tc.uv * sq);
  return parity(cell.x + cell.y + sq * (tc.tile.x + tc.tile.y));
}

double solidCheckerReference(const TextureDesc& t, const TexCoordD& tc) {
  const glm::dvec3 cell = glm::floor(tc.solid * double(t.squares));
  return parity(cell.x + cell.y + cell.z);
}

double noiseReference(const TextureDesc& t, const TexCoordD& tc) {
  return clamp01(0.5 + 0.5 * perlinNoise(tc.solid * double(t.scale)));
}

// Veins along the planes x + y = const, displaced by turbulence; cubing the [0,1] sine
// profile keeps the color2 veins thin.
double marbleReference(const TextureDesc& t, const TexCoordD& tc) {
  const glm::dvec3 q = tc.solid * double(t.scale);
  const double s = 0.5 + 0.5 * std::sin(glm::pi<double>() * (q.x + q.y) + double(t.strength) * turbulence(q, t.octaves));
  return clamp01(s * s * s);
}

// Rings around the y axis through the solid cube's centre, `scale` rings per unit radius,
// wobbled by turbulence stretched 4x along the axis (grain).
double woodReference(const TextureDesc& t, const TexCoordD& tc) {
  const glm::dvec3 q = tc.solid * double(t.scale);
  const double r = glm::length(glm::dvec2(tc.solid.x - 0.5, tc.solid.z - 0.5));
  const glm::dvec3 w(q.x, 0.25 * q.y, q.z);
  const double rings = double(t.scale) * r + double(t.strength) * turbulence(w, t.octaves);
  const double f = rings - std::floor(rings);
  return clamp01(f * f);
}

double turbulenceReference(const TextureDesc& t, const TexCoordD& tc) {
  return clamp01(double(t.strength) * turbulence(tc.solid * double(t.scale), t.octaves));
}

// Running bond: `columns` bricks per tile along u, twice as many rows along v; odd rows shifted
// half a brick towards +u; joints `mortar` brick heights wide, centred on the brick edges.
double bricksReference(const TextureDesc& t, const TexCoordD& tc) {
  const double columns = double(t.columns), rows = 2.0 * columns, mortar = double(t.mortar);
  const double v = (tc.tile.y + tc.uv.y) * rows;
  const double row = std::floor(v);
  const double u = (tc.tile.x + tc.uv.x) * columns - 0.5 * parity(row);
  const double fu = u - std::floor(u), fv = v - row;
  // A joint is mortar / rows wide in v and in u: mortar brick heights, mortar / 2 brick widths.
  const bool joint = std::fmin(fv, 1.0 - fv) < 0.5 * mortar || std::fmin(fu, 1.0 - fu) < 0.25 * mortar;
  return joint ? 1.0 : 0.0;
}

double dturbulenceReference(const TextureDesc& t, const TexCoordD& tc) {
  return clamp01(double(t.strength) * dturbulence(tc.solid * double(t.scale), t.octaves));
}
}  // namespace

// A case per row of shaders/kinds/kinds.h whose kind returns a blend factor (not FILTER IMAGE).
#define RAYTEX_REFERENCE_IMAGE(Kind, fn)
#define RAYTEX_REFERENCE_CLOSED_FORM(Kind, fn) \
  case TextureKind::Kind: return fn##Reference(texture, tc);
#define RAYTEX_REFERENCE_BAND_LIMITED(Kind, fn) RAYTEX_REFERENCE_CLOSED_FORM(Kind, fn)
#define RAYTEX_REFERENCE_ROW(ID, NAME, Kind, fn, file, COORD, FILTER, TABLE, COST) RAYTEX_REFERENCE_##FILTER(Kind, fn)

double textureBlendReference(const TextureDesc& texture, const TexCoordD& tc) {
  switch (texture.kind) {
    RAYTEX_TEXTURE_KINDS(RAYTEX_REFERENCE_ROW)
    default: break;
  }
  throw std::invalid_argument(std::string("textureBlendReference: no CPU reference for texture kind ") +
                              textureKindName(texture.kind));
}

glm::dvec3 textureColorReference(const TextureDesc& texture, const TexCoordD& tc) {
  const double t = textureBlendReference(texture, tc);
  const glm::dvec3 c1(texture.color1), c2(texture.color2);
  return c1 + (c2 - c1) * t;
}
