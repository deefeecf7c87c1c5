// The texture colour used as the diffuse coefficient (course notes: "the colour the
// texture returns is used as the diffuse reflection coefficient"). The CPU
// double-precision oracle is textureBlendReference / textureColorReference in
// host/texture.cpp; keep the two in step. Formulas: docs/textures.md.
//
// Needs (declared by the including kernel, after common.h, noise.glsl, mapping.glsl, and
// footprint.glsl when RAYTEX_FILTER_BOX is defined):
//   const uint TEXTURE_KINDS;  // bit (1u << TEX_*): the kinds on any shape (spec constants)
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
vec2 textureParity(vec2 x) { return mod(x, 2.0); }

// Bilinear (the sampler's filter) at column 1 - u, row 1 - v: v = 1 is the image's top
// row, and 1 - u undoes the mirror of the notes' (u, v) frames seen from outside
// (docs/textures.md, "Image orientation"). REPEAT wraps u; on the sphere (clampV) t is
// kept half a texel inside the image so the poles do not blend the top and bottom rows.
#ifdef RAYTEX_FILTER_BOX
// FILTER_BOX (docs/textures.md, "Image filtering"): trilinear lookups in the image's mip chain
// (linear-light box averages built on the host) over the sample's footprint, the Jacobian
// J = [dst/dx dst/dy] in texels. J's ellipse is split along its major axis into probes, each
// at the level of the longer of the minor axis and the probe spacing (anisotropic filtering
// in the shader: lavapipe's sampler anisotropy returned wrong texels in this compute kernel).
// The derivatives are analytic, so the sphere's u seam gets no wrong level (accuracy.md F2).
// At most IMAGE_MAX_PROBES probes on planes (beyond that the footprint is blurred along its
// minor axis, as hardware anisotropic filtering does); on spheres IMAGE_SPHERE_PROBES, since
// the map's anisotropy grows as 1/sin(colatitude) near the poles (33 at 1.7 degrees).
const float IMAGE_MAX_PROBES = 8.0;
const float IMAGE_SPHERE_PROBES = 32.0;
// The level is log2(width) - log2(3)/2: a mip texel (box of 2^l texels) under bilinear
// filtering (tent of half-width 2^l) has variance 4^l/4, a box of the footprint's width w
// has w^2/12; the bias makes the two equal (and with probes, the whole filter's variance
// along the major axis equals the footprint's box).
const float IMAGE_LOD_BIAS = -0.79248125;

vec3 imageTextureColor(Material m, TexCoord tc, Footprint fp) {
  vec2 st = vec2(1.0 - tc.uv.x, 1.0 - tc.uv.y);
  float layer = float(m.imageLayer);
  vec2 size = vec2(textureSize(images, 0).xy);
  float maxLevel = float(textureQueryLevels(images) - 1);
  float k = 1.0;         // probes
  vec2 step = vec2(0.0);  // st from one probe to the next
  float width2;           // squared width of each probe's footprint, in level-0 texels
  if (tc.clampV && tc.solid.x == 0.5 && tc.solid.z == 0.5) {
    // The exact pole of a sphere (n.x = n.z = 0, where the mapping sets u = 0.5): the
    // mapping's derivatives are 0/0 (they come out 0), but the footprint is a disc around the
    // pole: every u, and v within half a sample step of it, |dn| / 2pi (solid = (n + 1) / 2,
    // so dn = 2 ds). Probes all around the circle, in the middle of that band and as wide as
    // it: an equirectangular image's rows near a pole all picture the pole's surroundings and
    // change slowly along u.
    float band = min(max(length(fp.dsdx), length(fp.dsdy)) / float(TEXTURE_PI), 1.0);
    st.y = st.y < 0.5 ? 0.5 * band : 1.0 - 0.5 * band;
    k = IMAGE_SPHERE_PROBES;
    step = vec2(1.0 / k, 0.0);
    width2 = band * band * size.y * size.y;
  } else {
    // Steps of st = (1 - u, 1 - v) for one sample step in x and in y, in level-0 texels.
    vec2 dstdx = -fp.duvdx, dstdy = -fp.duvdy;
    // Near a sphere's poles du grows without bound, but no footprint covers more than every u.
    if (tc.clampV) {
      dstdx.x = clamp(dstdx.x, -1.0, 1.0);
      dstdy.x = clamp(dstdy.x, -1.0, 1.0);
    }
    vec2 dx = dstdx * size, dy = dstdy * size;
    // Principal axes of the footprint: the eigenvalues of J J^T, J = [dx dy], are the squared
    // semi-axes of its ellipse (the lengths of dx and dy overstate the minor axis when they
    // are skewed, as on the sphere away from the equator).
    float a = dx.x * dx.x + dy.x * dy.x, b = dx.x * dx.y + dy.x * dy.y, c = dx.y * dx.y + dy.y * dy.y;
    if (!(a + c < 1.0e30)) {  // non-finite or huge (a differential ray parallel to the surface)
      if (tc.clampV) st.y = 0.5;
      return textureLod(images, vec3(st, layer), maxLevel).rgb;
    }
    float dev = sqrt(0.25 * (a - c) * (a - c) + b * b);
    float major2 = 0.5 * (a + c) + dev, minor2 = max(0.5 * (a + c) - dev, 0.0);
    // Probes only where the footprint is longer than a texel: under magnification one
    // bilinear lookup at level 0 is exactly the point kernel's.
    if (major2 > 1.0) k = clamp(ceil(sqrt(major2 / max(minor2, 1.0e-30))), 1.0, tc.clampV ? IMAGE_SPHERE_PROBES : IMAGE_MAX_PROBES);
    width2 = max(minor2, major2 / (k * k));
    // The major axis: an eigenvector of J J^T, in the form without cancellation.
    vec2 axis = a >= c ? vec2(0.5 * (a - c) + dev, b) : vec2(b, 0.5 * (c - a) + dev);
    axis = dot(axis, axis) > 0.0 ? normalize(axis) : vec2(1.0, 0.0);
    step = axis * sqrt(major2) / (size * k);
  }
  float lod = clamp(0.5 * log2(max(width2, 1.0e-30)) + IMAGE_LOD_BIAS, 0.0, maxLevel);
  // On the sphere t stays half a texel of the coarser of the two levels blended inside the
  // image, so no level blends the two poles' rows. (Its height by shifting: lavapipe answers
  // textureSize(images, lod) with one invocation's lod for the whole SIMD group.)
  float h = float(max(int(size.y) >> int(ceil(lod)), 1));
  vec2 tRange = tc.clampV ? vec2(0.5 / h, 1.0 - 0.5 / h) : vec2(-1.0e30, 1.0e30);
  vec3 sum = vec3(0.0);
  for (float i = 0.5 - 0.5 * k; i < 0.5 * k; i += 1.0) {
    vec2 q = st + i * step;
    sum += textureLod(images, vec3(q.x, clamp(q.y, tRange.x, tRange.y), layer), lod).rgb;
  }
  return sum / k;
}
#else
vec3 imageTextureColor(Material m, TexCoord tc) {
  vec2 st = vec2(1.0 - tc.uv.x, 1.0 - tc.uv.y);
  if (tc.clampV) {
    float h = float(textureSize(images, 0).y);
    st.y = clamp(st.y, 0.5 / h, 1.0 - 0.5 / h);
  }
  return textureLod(images, vec3(st, float(m.imageLayer)), 0.0).rgb;
}
#endif

// Blend factors t in [0,1]: colour = mix(color1, color2, t). q = solid * scale, clamped
// (mapping.glsl, TEXCOORD_LIMIT) like every phase below: a huge scale or strength would
// overflow them, and floor, fract or sin of infinity is NaN.
vec3 noiseArgument(TexCoord tc, float scale) { return clampTexCoord(tc.solid * scale); }

// `squares` (rounded, >= 1) checks per side of one tile; the tile term keeps the
// pattern a proper checkerboard across tile borders for odd `squares`.
// Summed as parities: the cells and sq * tile of a huge sq overflow the sum (parity of a
// product: the product of parities; integer-valued floats, so exact).
float checkerBlend(Material m, TexCoord tc) {
  float sq = max(floor(m.params.z + 0.5), 1.0);
  vec2 cell = floor(tc.uv * sq);
  return textureParity(textureParity(cell.x) + textureParity(cell.y) +
                       textureParity(sq) * textureParity(tc.tile.x + tc.tile.y));
}

float solidCheckerBlend(Material m, TexCoord tc) {
  vec3 cell = floor(clampTexCoord(tc.solid * m.params.z));
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
  vec2 x = tc.uv * sq + textureParity(sq) * textureParity(tc.tile);
  vec2 w = clampTexCoord(uvWidth(fp) * sq);
  vec2 e = vec2(filteredParity(x.x, w.x), filteredParity(x.y, w.y));
  return clamp(0.5 - 0.5 * (1.0 - 2.0 * e.x) * (1.0 - 2.0 * e.y), 0.0, 1.0);
}

float filteredSolidCheckerBlend(Material m, TexCoord tc, Footprint fp) {
  vec3 x = clampTexCoord(tc.solid * m.params.z), w = clampTexCoord(solidWidth(fp) * m.params.z);
  vec3 a = vec3(1.0) - 2.0 * vec3(filteredParity(x.x, w.x), filteredParity(x.y, w.y), filteredParity(x.z, w.z));
  return clamp(0.5 - 0.5 * a.x * a.y * a.z, 0.0, 1.0);  // rounding may step just outside
}

#endif  // RAYTEX_FILTER_BOX

float noiseBlend(Material m, TexCoord tc) {
  return clamp(0.5 + 0.5 * perlinNoise(noiseArgument(tc, m.params.x)), 0.0, 1.0);
}

// Veins along the planes x + y = const, displaced by turbulence; cubing the
// sine's [0,1] profile makes the color2 veins thin.
float marbleBlend(Material m, TexCoord tc) {
  vec3 q = noiseArgument(tc, m.params.x);
  float s = 0.5 + 0.5 * sin(float(TEXTURE_PI) * (q.x + q.y) + clampTexCoord(m.params.y * turbulence(q, m.octaves)));
  return clamp(s * s * s, 0.0, 1.0);
}

// Rings around the y axis through the centre of the solid cube (0.5, *, 0.5),
// `scale` rings per unit radius, wobbled by turbulence stretched 4x along the axis
// (grain); the squared sawtooth gives soft early wood and a sharp ring edge.
float woodBlend(Material m, TexCoord tc) {
  float scale = m.params.x;
  vec3 q = noiseArgument(tc, scale);
  float r = length(tc.solid.xz - 0.5);
  float rings = clampTexCoord(scale * r) + clampTexCoord(m.params.y * turbulence(vec3(q.x, 0.25 * q.y, q.z), m.octaves));
  float f = rings - floor(rings);
  return clamp(f * f, 0.0, 1.0);
}

float turbulenceBlend(Material m, TexCoord tc) {
  return clamp(m.params.y * turbulence(noiseArgument(tc, m.params.x), m.octaves), 0.0, 1.0);
}

float dturbulenceBlend(Material m, TexCoord tc) {
  return clamp(m.params.y * dturbulence(noiseArgument(tc, m.params.x), m.octaves), 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
// --- Filtered noise kinds (FILTER_BOX; accuracy.md L5 and L6, docs/textures.md "Filtering
// the noise kinds"). Octaves finer than the footprint fade to their mean (noise.glsl,
// filteredTurbulence), and the periodic profiles of marble and wood are band-limited: the
// blur of their phase by the footprint (its linear change across it) and by the averaged-away
// turbulence octaves (their variance) fades the stripes to their mean. Zero width gives the
// point-sampled formulas above.

// The scalar footprint width of a noise kind, in lattice cells of its first octave: the length
// of the per-axis widths solidWidth(fp) (after wood's `stretch` of the noise argument) times
// `scale`. For a thin grazing footprint this is its long axis in any orientation (the largest
// component would read a diagonal one as 1/sqrt(2) of it); for a round one it is up to sqrt(3)
// times its diameter. Clamped so a parallel differential ray (FOOTPRINT_MAX) stays finite.
float noiseFootprintWidth(Footprint fp, float scale, vec3 stretch) {
  return min(length(solidWidth(fp) * stretch) * scale, 1.0e6);
}

// The average of sin(k x) over a phase interval of x `w` wide, relative to its value at the
// centre, for the harmonics k = 1, 2, 3: sin(k w/2) / (k w/2) (Quilez, "bandlimiting"), from
// one sin and one cos. Each is cut to 0 past its first zero (k w = 2 pi): there the footprint
// spans a whole period, and a linear phase (which gives the negative lobes) no longer
// describes it.
vec3 phaseBandLimits(float w) {
  float h = 0.5 * abs(w);
  if (h < 1.0e-3) return vec3(1.0);  // 1 - h^2/6: 1 in float
  float s = sin(h), c = cos(h);
  vec3 kh = h * vec3(1.0, 2.0, 3.0);
  vec3 limits = vec3(s, 2.0 * s * c, s * (3.0 - 4.0 * s * s)) / kh;
  return mix(limits, vec3(0.0), greaterThanEqual(kh, vec3(float(TEXTURE_PI))));  // a select
}

// noise fades to its mean, blend 0.5, as the footprint nears the lattice period.
float filteredNoiseBlend(Material m, TexCoord tc, Footprint fp) {
  float w = octaveWeight(noiseFootprintWidth(fp, m.params.x, vec3(1.0)), NOISE_WEIGHT_CELLS);
  if (w <= 0.0) return 0.5;
  return clamp(0.5 + 0.5 * w * perlinNoise(noiseArgument(tc, m.params.x)), 0.0, 1.0);
}

// marble's profile ((1 + sin x) / 2)^3 as a Fourier series, each harmonic k averaged over the
// footprint: 5/16 + 15/32 A1 sin x - 3/16 A2 cos 2x - 1/32 A3 sin 3x, where
// A_k = phaseBandLimits(a)_k phaseBandLimits(b)_k exp(-k^2 s^2 / 2): a, b the change of the
// stripe phase pi (q_x + q_y) across the footprint's two edges (a parallelogram: the product is
// the exact box average of a linear phase), s^2 the phase variance of the averaged-away
// turbulence (strength^2 times filteredTurbulence's `unresolved`; exp(-k^2 s^2 / 2) is the mean
// of cos(k d) for a Gaussian d). Far away it tends to 5/16, the profile's mean; A_k = 1 gives
// marbleBlend. cos 2x and sin 3x come from sin x: one sin as before.
float filteredMarbleBlend(Material m, TexCoord tc, Footprint fp) {
  float scale = m.params.x, strength = m.params.y;
  vec3 q = noiseArgument(tc, scale);
  float unresolved;
  float turb = filteredTurbulence(q, m.octaves, noiseFootprintWidth(fp, scale, vec3(1.0)), unresolved);
  float s = sin(float(TEXTURE_PI) * (q.x + q.y) + clampTexCoord(strength * turb));
  float a = float(TEXTURE_PI) * scale * (fp.dsdx.x + fp.dsdx.y);
  float b = float(TEXTURE_PI) * scale * (fp.dsdy.x + fp.dsdy.y);
  float e1 = exp(-0.5 * clampTexCoord(strength * strength) * unresolved), e4 = (e1 * e1) * (e1 * e1);
  vec3 k = phaseBandLimits(a) * phaseBandLimits(b) * vec3(e1, e4, e4 * e4 * e1);  // exp(-k^2 s^2/2)
  float t = 5.0 / 16.0 + (15.0 / 32.0) * k.x * s - (3.0 / 16.0) * k.y * (1.0 - 2.0 * s * s) -
            (1.0 / 32.0) * k.z * s * (3.0 - 4.0 * s * s);
  return clamp(t, 0.0, 1.0);
}

// Integral from 0 to x of fract(u)^2: each whole ring adds 1/3.
float woodRingIntegral(float x) {
  float f = fract(x);
  return (floor(x) + f * f * f) / 3.0;
}

// wood's sawtooth fract(g)^2 averaged in closed form over a box of width w in ring units
// (mean 1/3 once w spans rings): w^2 = a^2 + b^2 + 12 s^2, with a, b the change of scale * r
// across the footprint's two edges and s^2 the variance of the averaged-away turbulence
// (strength^2 times `unresolved`); a box of width sqrt(12) s has the same variance. w -> 0
// gives woodBlend.
float filteredWoodBlend(Material m, TexCoord tc, Footprint fp) {
  float scale = m.params.x, strength = m.params.y;
  vec3 stretch = vec3(1.0, 0.25, 1.0);
  float unresolved;
  float turb = filteredTurbulence(noiseArgument(tc, scale) * stretch, m.octaves, noiseFootprintWidth(fp, scale, stretch),
                                  unresolved);
  vec2 d = tc.solid.xz - 0.5;
  float r = length(d);
  float rings = clampTexCoord(scale * r) + clampTexCoord(strength * turb);
  vec2 radial = r > 0.0 ? d / r : vec2(0.0);
  float a = scale * dot(radial, fp.dsdx.xz), b = scale * dot(radial, fp.dsdy.xz);
  float w = sqrt(a * a + b * b + 12.0 * strength * strength * unresolved);
  float x = rings - floor(rings);  // reduced first: the integrals' difference keeps its precision
  if (!(w >= 1.0e-4)) return clamp(x * x, 0.0, 1.0);  // narrower than float resolution: point
  w = min(w, 1.0e4);                                  // the mean to ~1e-4; keeps floor() small
  return clamp((woodRingIntegral(x + 0.5 * w) - woodRingIntegral(x - 0.5 * w)) / w, 0.0, 1.0);
}

float filteredTurbulenceBlend(Material m, TexCoord tc, Footprint fp) {
  float unresolved;
  float cells = noiseFootprintWidth(fp, m.params.x, vec3(1.0));
  return clamp(m.params.y * filteredTurbulence(noiseArgument(tc, m.params.x), m.octaves, cells, unresolved), 0.0, 1.0);
}

float filteredDturbulenceBlend(Material m, TexCoord tc, Footprint fp) {
  float cells = noiseFootprintWidth(fp, m.params.x, vec3(1.0));
  return clamp(m.params.y * filteredDturbulence(noiseArgument(tc, m.params.x), m.octaves, cells), 0.0, 1.0);
}
#endif  // RAYTEX_FILTER_BOX

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

// With RAYTEX_FILTER_BOX the checkers average over the footprint fp in closed form and the
// noise kinds are frequency-clamped and band-limited to it.
#ifdef RAYTEX_FILTER_BOX
vec3 textureColor(Material m, TexCoord tc, Footprint fp) {
#else
vec3 textureColor(Material m, TexCoord tc) {
#endif
  uint kind = m.textureKind;
  float t = -1.0;  // stays < 0 for untextured materials and unknown kinds
  if (TEXTURE_KIND_PRESENT(TEX_IMAGE)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_IMAGE) return imageTextureColor(m, tc, fp);
#else
    if (kind == TEX_IMAGE) return imageTextureColor(m, tc);
#endif
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
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_NOISE) t = filteredNoiseBlend(m, tc, fp);
#else
    if (kind == TEX_NOISE) t = noiseBlend(m, tc);
#endif
  }
  if (TEXTURE_KIND_PRESENT(TEX_MARBLE)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_MARBLE) t = filteredMarbleBlend(m, tc, fp);
#else
    if (kind == TEX_MARBLE) t = marbleBlend(m, tc);
#endif
  }
  if (TEXTURE_KIND_PRESENT(TEX_WOOD)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_WOOD) t = filteredWoodBlend(m, tc, fp);
#else
    if (kind == TEX_WOOD) t = woodBlend(m, tc);
#endif
  }
  if (TEXTURE_KIND_PRESENT(TEX_TURBULENCE)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_TURBULENCE) t = filteredTurbulenceBlend(m, tc, fp);
#else
    if (kind == TEX_TURBULENCE) t = turbulenceBlend(m, tc);
#endif
  }
  if (TEXTURE_KIND_PRESENT(TEX_DTURBULENCE)) {
#ifdef RAYTEX_FILTER_BOX
    if (kind == TEX_DTURBULENCE) t = filteredDturbulenceBlend(m, tc, fp);
#else
    if (kind == TEX_DTURBULENCE) t = dturbulenceBlend(m, tc);
#endif
  }
  if (t < -0.5) return m.diffuse.rgb;  // TEX_NONE (far from any rounded blend value)
  return mix(m.color1.rgb, m.color2.rgb, t);
}

#endif  // RAYTEX_TEXTURES_GLSL
