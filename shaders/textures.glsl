// The texture colour used as the diffuse coefficient (course notes: "the colour the
// texture returns is used as the diffuse reflection coefficient"). The CPU
// double-precision oracle is textureBlendReference / textureColorReference in
// host/texture.cpp; keep the two in step. Formulas: docs/textures.md.
//
// Needs (declared by the including kernel, after common.h, noise.glsl, mapping.glsl, and
// footprint.glsl when RAYTEX_FILTER_BOX is defined):
//   layout(constant_id = SPEC_TEXTURE_KINDS) const uint TEXTURE_KINDS;  // bit (1u << TEX_*)
//   layout(binding = BINDING_IMAGES) uniform sampler2DArray images;
// Every kind's code sits behind its TEXTURE_KINDS bit, so a pipeline specialised
// for a scene keeps only the kinds it uses (a checker-only scene has no noise code).
#ifndef RAYTEX_TEXTURES_GLSL
#define RAYTEX_TEXTURES_GLSL

#define TEXTURE_PI 3.14159265358979323846

// A spec-constant expression: the driver folds it and drops absent kinds' code.
#define TEXTURE_KIND_PRESENT(kind) ((TEXTURE_KINDS & (1u << (kind))) != 0u)

// 0 for an even integer-valued x, 1 for an odd one (float mod: no int casts or %
// of negative values; accuracy.md F1).
float textureParity(float x) { return mod(x, 2.0); }

// Bilinear (the sampler's filter) at column 1 - u, row 1 - v: v = 1 is the image's top
// row, and 1 - u undoes the mirror of the notes' (u, v) frames seen from outside
// (docs/textures.md, "Image orientation"). REPEAT wraps u; on the sphere (clampV) t is
// kept half a texel inside the image so the poles do not blend the top and bottom rows.
vec3 imageTextureColor(Material m, TexCoord tc) {
  vec2 st = vec2(1.0 - tc.uv.x, 1.0 - tc.uv.y);
  if (tc.clampV) {
    float h = float(textureSize(images, 0).y);
    st.y = clamp(st.y, 0.5 / h, 1.0 - 0.5 / h);
  }
  return textureLod(images, vec3(st, float(m.imageLayer)), 0.0).rgb;
}

// Blend factors t in [0,1]: colour = mix(color1, color2, t). q = solid * scale.

// `squares` (rounded, >= 1) checks per side of one tile; the tile term keeps the
// pattern a proper checkerboard across tile borders for odd `squares`.
float checkerBlend(Material m, TexCoord tc) {
  float sq = max(floor(m.params.z + 0.5), 1.0);
  vec2 cell = floor(tc.uv * sq);
  return textureParity(cell.x + cell.y + sq * (tc.tile.x + tc.tile.y));
}

float solidCheckerBlend(Material m, TexCoord tc) {
  vec3 cell = floor(tc.solid * m.params.z);
  return textureParity(cell.x + cell.y + cell.z);
}

#ifdef RAYTEX_FILTER_BOX
// --- Box-filtered checkers (FILTER_BOX): the exact average over the footprint's
// axis-aligned box in texture space (Quilez, "checkerfiltering"; pbrt-v3 Checkerboard).

// Integral from 0 to x of the parity of floor(x) (0 on [0,1), 1 on [1,2), period 2).
float parityIntegral(float x) { return floor(0.5 * x) + max(0.0, 2.0 * fract(0.5 * x) - 1.0); }

// Average of the parity of floor over [x - w/2, x + w/2]. x is reduced mod 2 first so the
// difference of integrals does not cancel far from the origin.
float filteredParity(float x, float w) {
  x = mod(x, 2.0);
  if (w < 1.0e-4) return step(1.0, x);  // narrower than float resolution here: point sample
  return (parityIntegral(x + 0.5 * w) - parityIntegral(x - 0.5 * w)) / w;
}

// Parity of a sum of independent axes under a separable box: with e_i the average parity
// of axis i, the average of their sum mod 2 is (1 - prod(1 - 2 e_i)) / 2.
float filteredCheckerBlend(Material m, TexCoord tc, Footprint fp) {
  float sq = max(floor(m.params.z + 0.5), 1.0);
  // floor(uv sq) + sq tile, mod 2 without forming the large unwrapped coordinate.
  vec2 x = tc.uv * sq + mod(sq * tc.tile, 2.0);
  vec2 w = uvWidth(fp) * sq;
  vec2 e = vec2(filteredParity(x.x, w.x), filteredParity(x.y, w.y));
  return clamp(0.5 - 0.5 * (1.0 - 2.0 * e.x) * (1.0 - 2.0 * e.y), 0.0, 1.0);
}

float filteredSolidCheckerBlend(Material m, TexCoord tc, Footprint fp) {
  vec3 x = tc.solid * m.params.z, w = solidWidth(fp) * m.params.z;
  vec3 a = vec3(1.0) - 2.0 * vec3(filteredParity(x.x, w.x), filteredParity(x.y, w.y), filteredParity(x.z, w.z));
  return clamp(0.5 - 0.5 * a.x * a.y * a.z, 0.0, 1.0);  // rounding may step just outside
}

#endif  // RAYTEX_FILTER_BOX

float noiseBlend(Material m, TexCoord tc) {
  return clamp(0.5 + 0.5 * perlinNoise(tc.solid * m.params.x), 0.0, 1.0);
}

// Veins along the planes x + y = const, displaced by turbulence; cubing the
// sine's [0,1] profile makes the color2 veins thin.
float marbleBlend(Material m, TexCoord tc) {
  vec3 q = tc.solid * m.params.x;
  float s = 0.5 + 0.5 * sin(float(TEXTURE_PI) * (q.x + q.y) + m.params.y * turbulence(q, m.octaves));
  return clamp(s * s * s, 0.0, 1.0);
}

// Rings around the y axis through the centre of the solid cube (0.5, *, 0.5),
// `scale` rings per unit radius, wobbled by turbulence stretched 4x along the axis
// (grain); the squared sawtooth gives soft early wood and a sharp ring edge.
float woodBlend(Material m, TexCoord tc) {
  float scale = m.params.x;
  vec3 q = tc.solid * scale;
  float r = length(tc.solid.xz - 0.5);
  float rings = scale * r + m.params.y * turbulence(vec3(q.x, 0.25 * q.y, q.z), m.octaves);
  float f = rings - floor(rings);
  return clamp(f * f, 0.0, 1.0);
}

float turbulenceBlend(Material m, TexCoord tc) {
  return clamp(m.params.y * turbulence(tc.solid * m.params.x, m.octaves), 0.0, 1.0);
}

float dturbulenceBlend(Material m, TexCoord tc) {
  return clamp(m.params.y * dturbulence(tc.solid * m.params.x, m.octaves), 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
// Kinds whose FILTER_BOX value is a closed-form average over a footprint box.
bool hasClosedFormFilter(uint kind) { return kind == TEX_CHECKER || kind == TEX_SOLID_CHECKER; }

// The box-filtered blend factor of a hasClosedFormFilter kind.
float filteredBlend(Material m, TexCoord tc, Footprint fp) {
  if (TEXTURE_KIND_PRESENT(TEX_CHECKER)) {
    if (m.textureKind == TEX_CHECKER) return filteredCheckerBlend(m, tc, fp);
  }
  if (TEXTURE_KIND_PRESENT(TEX_SOLID_CHECKER)) {
    if (m.textureKind == TEX_SOLID_CHECKER) return filteredSolidCheckerBlend(m, tc, fp);
  }
  return 0.0;
}
#endif

// With RAYTEX_FILTER_BOX the closed-form kinds average over the footprint fp.
#ifdef RAYTEX_FILTER_BOX
vec3 textureColor(Material m, TexCoord tc, Footprint fp) {
#else
vec3 textureColor(Material m, TexCoord tc) {
#endif
  uint kind = m.textureKind;
  float t = -1.0;  // stays < 0 for untextured materials and unknown kinds
  if (TEXTURE_KIND_PRESENT(TEX_IMAGE)) {
    if (kind == TEX_IMAGE) return imageTextureColor(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_CHECKER)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_CHECKER) t = filteredCheckerBlend(m, tc, fp);
#else
    if (kind == TEX_CHECKER) t = checkerBlend(m, tc);
#endif
  }
  if (TEXTURE_KIND_PRESENT(TEX_SOLID_CHECKER)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_SOLID_CHECKER) t = filteredSolidCheckerBlend(m, tc, fp);
#else
    if (kind == TEX_SOLID_CHECKER) t = solidCheckerBlend(m, tc);
#endif
  }
  if (TEXTURE_KIND_PRESENT(TEX_NOISE)) {
    if (kind == TEX_NOISE) t = noiseBlend(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_MARBLE)) {
    if (kind == TEX_MARBLE) t = marbleBlend(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_WOOD)) {
    if (kind == TEX_WOOD) t = woodBlend(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_TURBULENCE)) {
    if (kind == TEX_TURBULENCE) t = turbulenceBlend(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_DTURBULENCE)) {
    if (kind == TEX_DTURBULENCE) t = dturbulenceBlend(m, tc);
  }
  if (t < -0.5) return m.diffuse.rgb;  // TEX_NONE (far from any rounded blend value)
  return mix(m.color1.rgb, m.color2.rgb, t);
}

#endif  // RAYTEX_TEXTURES_GLSL
