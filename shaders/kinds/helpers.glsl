// Pieces several texture kinds share: parities (the checkers), the noise argument and, for
// the box-filtered module, the parity integrals and the band limits of periodic profiles.
#ifndef RAYTEX_KIND_HELPERS_GLSL
#define RAYTEX_KIND_HELPERS_GLSL

// 0 for an even integer-valued x, 1 for an odd one (float mod: an int cast truncates towards
// 0, and GLSL leaves % of a negative value undefined).
float textureParity(float x) { return mod(x, 2.0); }
vec2 textureParity(vec2 x) { return mod(x, 2.0); }

// Blend factors t in [0,1]: colour = mix(color1, color2, t). q = solid * scale, clamped
// (mapping.glsl, TEXCOORD_LIMIT) like every phase below: a huge scale or strength would
// overflow them, and floor, fract or sin of infinity is NaN.
vec3 noiseArgument(TexCoord tc, float scale) { return clampTexCoord(tc.solid * scale); }

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

// --- Filtered noise kinds (FILTER_BOX; docs/textures.md, "Filtering the noise kinds").
// Octaves finer than the footprint fade to their mean (noise.glsl, filteredTurbulence), and
// the periodic profiles of marble and wood are band-limited: the blur of their phase by the
// footprint (its linear change across it) and by the averaged-away turbulence octaves (their
// variance) fades the stripes to their mean. Zero width gives the point-sampled formulas
// above.

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

#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_HELPERS_GLSL
