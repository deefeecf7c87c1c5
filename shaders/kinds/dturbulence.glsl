// dturbulence: turbulence whose octaves are damped by the slope of those below; box: as
// turbulence. Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_DTURBULENCE_GLSL
#define RAYTEX_KIND_DTURBULENCE_GLSL

float dturbulencePoint(Material m, TexCoord tc) {
  return clamp(m.params.y * dturbulence(noiseArgument(tc, m.params.x), m.octaves), 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
float dturbulenceBox(Material m, TexCoord tc, Footprint fp) {
  float cells = noiseFootprintWidth(fp, m.params.x, vec3(1.0));
  return clamp(m.params.y * filteredDturbulence(noiseArgument(tc, m.params.x), m.octaves, cells), 0.0, 1.0);
}
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_DTURBULENCE_GLSL
