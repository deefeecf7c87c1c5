// The texture colour used as the diffuse coefficient (course notes: "the colour the
// texture returns is used as the diffuse reflection coefficient"), picked by kind in one
// dispatch, textureColor. Each kind lives in shaders/kinds/<kind>.glsl with its point-sampled evaluation
// (<kind>Point) and, in the box-filtered module, its footprint-filtered one (<kind>Box); its
// host row is in host/scene/texture_kinds.cpp and its double-precision oracle in host/reference/texture.cpp.
// Formulas: docs/textures.md. Adding a kind: docs/adding-a-texture.md.
//
// Needs (declared by the including kernel, after common.h, noise.glsl, mapping.glsl, and
// footprint.glsl when RAYTEX_FILTER_BOX is defined):
//   const uint TEXTURE_KINDS;  // bit (1u << TEX_*): the kinds on any shape (spec constants)
//   const uint IMAGE_COUNT;  // image files in use (spec constant)
//   layout(binding = BINDING_IMAGES) uniform sampler2D images[MAX_IMAGES];
// Every case sits behind its TEXTURE_KINDS bit, so a pipeline specialised for a scene keeps
// only the kinds it uses (a checker-only scene has no noise code).
#ifndef RAYTEX_TEXTURES_GLSL
#define RAYTEX_TEXTURES_GLSL

#define TEXTURE_PI 3.14159265358979323846

// A spec-constant expression: the driver folds it and drops absent kinds' code.
#define TEXTURE_KIND_PRESENT(kind) ((TEXTURE_KINDS & (1u << (kind))) != 0u)

#include "kinds/helpers.glsl"
#include "kinds/image.glsl"
#include "kinds/checker.glsl"
#include "kinds/solid_checker.glsl"
#include "kinds/noise.glsl"
#include "kinds/marble.glsl"
#include "kinds/wood.glsl"
#include "kinds/turbulence.glsl"
#include "kinds/dturbulence.glsl"
#include "kinds/bricks.glsl"

// One kind's evaluation in this module: point-sampled, or filtered over the footprint fp.
#ifdef RAYTEX_FILTER_BOX
#define TEXTURE_EVAL(name) name##Box(m, tc, fp)
#else
#define TEXTURE_EVAL(name) name##Point(m, tc)
#endif
// A case of the dispatch for a kind that returns a blend factor t: colour = mix(color1, color2, t).
// Each case is guarded by its kind's specialisation bit, so absent kinds compile to nothing.
// One mix after the switch, not one per case: the kernel built around a scene's values then
// rounds exactly as the one reading them.
#define TEXTURE_BLEND_CASE(kind, name) \
  case kind:                           \
    if (TEXTURE_KIND_PRESENT(kind)) t = TEXTURE_EVAL(name); \
    break;

// Whether the kind reads the solid coordinate (the others, and untextured materials, the 2D one).
bool readsSolidCoord(uint kind) { return kind != TEX_NONE && ((TEX_2D_KINDS >> kind) & 1u) == 0u; }

// The coordinate the material's kind reads: the solid one, or (u, v, 0).
vec3 mappedCoord(Material m, TexCoord tc) { return readsSolidCoord(m.textureKind) ? tc.solid : vec3(tc.uv, 0.0); }

#ifdef RAYTEX_FILTER_BOX
vec3 textureColor(Material m, TexCoord tc, Footprint fp) {
#else
vec3 textureColor(Material m, TexCoord tc) {
#endif
  float t = -1.0;  // stays < 0 for untextured materials
  switch (m.textureKind) {
    case TEX_IMAGE:
      if (TEXTURE_KIND_PRESENT(TEX_IMAGE)) return TEXTURE_EVAL(image);
      break;
    TEXTURE_BLEND_CASE(TEX_CHECKER, checker)
    TEXTURE_BLEND_CASE(TEX_SOLID_CHECKER, solidChecker)
    TEXTURE_BLEND_CASE(TEX_NOISE, noise)
    TEXTURE_BLEND_CASE(TEX_MARBLE, marble)
    TEXTURE_BLEND_CASE(TEX_WOOD, wood)
    TEXTURE_BLEND_CASE(TEX_TURBULENCE, turbulence)
    TEXTURE_BLEND_CASE(TEX_DTURBULENCE, dturbulence)
    TEXTURE_BLEND_CASE(TEX_BRICKS, bricks)
    default:
      break;
  }
  if (t < -0.5) return m.diffuse.rgb;  // TEX_NONE (far from any rounded blend value)
  return mix(m.color1.rgb, m.color2.rgb, t);
}

#ifdef RAYTEX_FILTER_BOX
// Kinds whose box-filtered blend is a closed-form average over a footprint box: a long
// footprint is split into probes along its long axis (trace.comp.glsl, albedoAt).
#define TEXTURE_CLOSED_FORM_KINDS ((1u << TEX_CHECKER) | (1u << TEX_SOLID_CHECKER) | (1u << TEX_BRICKS))
bool hasClosedFormFilter(uint kind) { return ((TEXTURE_CLOSED_FORM_KINDS >> kind) & 1u) != 0u; }

// The box-filtered blend factor of a closed-form kind.
float filteredBlend(Material m, TexCoord tc, Footprint fp) {
  if (TEXTURE_KIND_PRESENT(TEX_CHECKER) && m.textureKind == TEX_CHECKER) return checkerBox(m, tc, fp);
  if (TEXTURE_KIND_PRESENT(TEX_SOLID_CHECKER) && m.textureKind == TEX_SOLID_CHECKER) return solidCheckerBox(m, tc, fp);
  if (TEXTURE_KIND_PRESENT(TEX_BRICKS) && m.textureKind == TEX_BRICKS) return bricksBox(m, tc, fp);
  return 0.0;
}

// How many cells of a closed-form kind the footprint step (duv, ds) spans.
float filteredCells(Material m, vec2 duv, vec3 ds) {
  if (TEXTURE_KIND_PRESENT(TEX_CHECKER) && m.textureKind == TEX_CHECKER) return checkerCells(m, duv, ds);
  if (TEXTURE_KIND_PRESENT(TEX_SOLID_CHECKER) && m.textureKind == TEX_SOLID_CHECKER) return solidCheckerCells(m, duv, ds);
  if (TEXTURE_KIND_PRESENT(TEX_BRICKS) && m.textureKind == TEX_BRICKS) return bricksCells(m, duv, ds);
  return 0.0;
}
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_TEXTURES_GLSL
