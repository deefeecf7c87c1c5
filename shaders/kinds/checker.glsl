// checker: squares alternating on the (u, v) of the shape's mapping, point-sampled or averaged
// over the footprint in closed form (box). Oracle: textureBlendReference (host/reference/texture.cpp).
#ifndef RAYTEX_KIND_CHECKER_GLSL
#define RAYTEX_KIND_CHECKER_GLSL

// `squares` (rounded, >= 1) checks per side of one tile; the tile term keeps the
// pattern a proper checkerboard across tile borders for odd `squares`.
// Summed as parities: the cells and sq * tile of a huge sq overflow the sum (parity of a
// product: the product of parities; integer-valued floats, so exact).
float checkerPoint(Material m, TexCoord tc) {
  float sq = max(floor(m.params.z + 0.5), 1.0);
  vec2 cell = floor(tc.uv * sq);
  return textureParity(textureParity(cell.x) + textureParity(cell.y) +
                       textureParity(sq) * textureParity(tc.tile.x + tc.tile.y));
}

#ifdef RAYTEX_FILTER_BOX

// Parity of a sum of independent axes under a separable box: with e_i the average parity
// of axis i, the average of their sum mod 2 is (1 - prod(1 - 2 e_i)) / 2.
float checkerBox(Material m, TexCoord tc, Footprint fp) {
  float sq = max(floor(m.params.z + 0.5), 1.0);
  // floor(uv sq) + sq tile, mod 2 without forming the large unwrapped coordinate.
  vec2 x = tc.uv * sq + textureParity(sq) * textureParity(tc.tile);
  vec2 w = clampTexCoord(uvWidth(fp) * sq);
  vec2 e = vec2(filteredParity(x.x, w.x), filteredParity(x.y, w.y));
  return clamp(0.5 - 0.5 * (1.0 - 2.0 * e.x) * (1.0 - 2.0 * e.y), 0.0, 1.0);
}

// Checks a footprint step (duv, ds) spans: where a long footprint is split into probes (box).
float checkerCells(Material m, vec2 duv, vec3 ds) { return length(duv) * max(floor(m.params.z + 0.5), 1.0); }
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_CHECKER_GLSL
