// turbulence: a sum of |noise| octaves; box: octaves finer than the footprint fade to their
// mean. Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_TURBULENCE_GLSL
#define RAYTEX_KIND_TURBULENCE_GLSL

float turbulencePoint(Material m, TexCoord tc) {
  return clamp(m.params.y * turbulence(noiseArgument(tc, m.params.x), m.octaves), 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
float turbulenceBox(Material m, TexCoord tc, Footprint fp) {
  float unresolved;
  float cells = noiseFootprintWidth(fp, m.params.x, vec3(1.0));
  return clamp(m.params.y * filteredTurbulence(noiseArgument(tc, m.params.x), m.octaves, cells, unresolved), 0.0, 1.0);
}
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_TURBULENCE_GLSL
