// solid_checker: cubes alternating in the solid coordinate, point-sampled or averaged over the
// footprint in closed form (box). Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_SOLID_CHECKER_GLSL
#define RAYTEX_KIND_SOLID_CHECKER_GLSL

float solidCheckerPoint(Material m, TexCoord tc) {
  vec3 cell = floor(clampTexCoord(tc.solid * m.params.z));
  return textureParity(cell.x + cell.y + cell.z);
}

#ifdef RAYTEX_FILTER_BOX
float solidCheckerBox(Material m, TexCoord tc, Footprint fp) {
  vec3 x = clampTexCoord(tc.solid * m.params.z), w = clampTexCoord(solidWidth(fp) * m.params.z);
  vec3 a = vec3(1.0) - 2.0 * vec3(filteredParity(x.x, w.x), filteredParity(x.y, w.y), filteredParity(x.z, w.z));
  return clamp(0.5 - 0.5 * a.x * a.y * a.z, 0.0, 1.0);  // rounding may step just outside
}

// Checks a footprint step (duv, ds) spans: where a long footprint is split into probes (box).
float solidCheckerCells(Material m, vec2 duv, vec3 ds) { return length(ds) * m.params.z; }
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_SOLID_CHECKER_GLSL
