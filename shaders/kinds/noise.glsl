// noise: Perlin noise of the solid coordinate; box: faded to its mean as the footprint nears the
// lattice period. Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_NOISE_GLSL
#define RAYTEX_KIND_NOISE_GLSL

float noisePoint(Material m, TexCoord tc) {
  return clamp(0.5 + 0.5 * perlinNoise(noiseArgument(tc, m.params.x)), 0.0, 1.0);
}

#ifdef RAYTEX_FILTER_BOX
// noise fades to its mean, blend 0.5, as the footprint nears the lattice period.
float noiseBox(Material m, TexCoord tc, Footprint fp) {
  float w = octaveWeight(noiseFootprintWidth(fp, m.params.x, vec3(1.0)), NOISE_WEIGHT_CELLS);
#ifdef RAYTEX_AOV
  keepOctavesPass(w > 0.0 ? 1.0 : 0.0);
#endif
  if (w <= 0.0) return 0.5;
  return clamp(0.5 + 0.5 * w * perlinNoise(noiseArgument(tc, m.params.x)), 0.0, 1.0);
}
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_NOISE_GLSL
