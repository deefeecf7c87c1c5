// wood: rings around the solid cube's y axis wobbled by turbulence; box: the sawtooth averaged
// in closed form. Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_WOOD_GLSL
#define RAYTEX_KIND_WOOD_GLSL

// Rings around the y axis through the centre of the solid cube (0.5, *, 0.5),
// `scale` rings per unit radius, wobbled by turbulence stretched 4x along the axis
// (grain); the squared sawtooth gives soft early wood and a sharp ring edge.
float woodPoint(Material m, TexCoord tc) {
  float scale = m.params.x;
  vec3 q = noiseArgument(tc, scale);
  float r = length(tc.solid.xz - 0.5);
  float rings = clampTexCoord(scale * r) + clampTexCoord(m.params.y * turbulence(vec3(q.x, 0.25 * q.y, q.z), m.octaves));
  float f = rings - floor(rings);
  return clamp(f * f, 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
// Integral from 0 to x of fract(u)^2: each whole ring adds 1/3.
float woodRingIntegral(float x) {
  float f = fract(x);
  return (floor(x) + f * f * f) / 3.0;
}

// wood's sawtooth fract(g)^2 averaged in closed form over a box of width w in ring units
// (mean 1/3 once w spans rings): w^2 = a^2 + b^2 + 12 s^2, with a, b the change of scale * r
// across the footprint's two edges and s^2 the variance of the averaged-away turbulence
// (strength^2 times `unresolved`); a box of width sqrt(12) s has the same variance. w -> 0
// gives woodPoint.
float woodBox(Material m, TexCoord tc, Footprint fp) {
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
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_WOOD_GLSL
