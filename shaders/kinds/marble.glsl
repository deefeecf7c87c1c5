// marble: veins of a sine displaced by turbulence; box: the profile band-limited to the
// footprint. Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_MARBLE_GLSL
#define RAYTEX_KIND_MARBLE_GLSL

// Veins along the planes x + y = const, displaced by turbulence; cubing the
// sine's [0,1] profile makes the color2 veins thin.
float marblePoint(Material m, TexCoord tc) {
  vec3 q = noiseArgument(tc, m.params.x);
  float s = 0.5 + 0.5 * sin(float(TEXTURE_PI) * (q.x + q.y) + clampTexCoord(m.params.y * turbulence(q, m.octaves)));
  return clamp(s * s * s, 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
// marble's profile ((1 + sin x) / 2)^3 as a Fourier series, each harmonic k averaged over the
// footprint: 5/16 + 15/32 A1 sin x - 3/16 A2 cos 2x - 1/32 A3 sin 3x, where
// A_k = phaseBandLimits(a)_k phaseBandLimits(b)_k exp(-k^2 s^2 / 2): a, b the change of the
// stripe phase pi (q_x + q_y) across the footprint's two edges (a parallelogram: the product is
// the exact box average of a linear phase), s^2 the phase variance of the averaged-away
// turbulence (strength^2 times filteredTurbulence's `unresolved`; exp(-k^2 s^2 / 2) is the mean
// of cos(k d) for a Gaussian d). Far away it tends to 5/16, the profile's mean; A_k = 1 gives
// marblePoint. cos 2x and sin 3x come from sin x: one sin, as in marblePoint.
float marbleBox(Material m, TexCoord tc, Footprint fp) {
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
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_MARBLE_GLSL
