// The texture colour used as the diffuse coefficient (course notes: "the colour the
// texture returns is used as the diffuse reflection coefficient"). The CPU
// double-precision oracle is textureBlendReference / textureColorReference in
// host/texture.cpp; keep the two in step. Formulas: docs/textures.md.
//
// Needs (declared by the including kernel, after common.h, noise.glsl, mapping.glsl):
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

vec3 textureColor(Material m, TexCoord tc) {
  uint kind = m.textureKind;
  float t = -1.0;  // stays < 0 for untextured materials and unknown kinds
  if (TEXTURE_KIND_PRESENT(TEX_IMAGE)) {
    if (kind == TEX_IMAGE) return imageTextureColor(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_CHECKER)) {
    if (kind == TEX_CHECKER) t = checkerBlend(m, tc);
  }
  if (TEXTURE_KIND_PRESENT(TEX_SOLID_CHECKER)) {
    if (kind == TEX_SOLID_CHECKER) t = solidCheckerBlend(m, tc);
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
  if (t < 0.0) return m.diffuse.rgb;  // TEX_NONE
  return mix(m.color1.rgb, m.color2.rgb, t);
}

#endif  // RAYTEX_TEXTURES_GLSL
