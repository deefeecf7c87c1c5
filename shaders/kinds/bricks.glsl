// bricks: running bond on the (u, v) of the shape's mapping, point-sampled or averaged over the
// footprint in closed form (box). Oracle: bricksReference (host/reference/texture.cpp). docs/textures.md,
// "bricks".
//
// `columns` C bricks per tile along u (m.params.z) and 2C rows along v, so a brick is twice as
// wide as it is high; odd rows (floor(v 2C) odd) shifted half a brick towards +u; joints
// `mortar` brick heights wide (m.params.w), centred on the brick edges: within mortar/2 of a
// row edge in row units, within mortar/4 of a brick edge in brick-width units. t = 1 in a joint
// (color2, mortar), 0 in a brick (color1).
#ifndef RAYTEX_KIND_BRICKS_GLSL
#define RAYTEX_KIND_BRICKS_GLSL

// Whole tiles add whole bricks (tile.x C) and an even number of rows (tile.y 2C), so the
// pattern needs only the wrapped (u, v): no large unwrapped coordinate is formed.
float bricksPoint(Material m, TexCoord tc) {
  float columns = m.params.z, mortar = m.params.w;
  float v = tc.uv.y * (2.0 * columns);
  float row = floor(v);
  float u = tc.uv.x * columns - 0.5 * textureParity(row);
  float fu = fract(u), fv = v - row;
  bool joint = min(fv, 1.0 - fv) < 0.5 * mortar || min(fu, 1.0 - fu) < 0.25 * mortar;
  return joint ? 1.0 : 0.0;
}

#ifdef RAYTEX_FILTER_BOX
// Integral from 0 to x of a row's bricks along u: 1 inside a brick, 0 within a of a whole number
// (a joint); each whole brick adds 1 - 2a.
float brickRowIntegral(float x, float a) {
  float whole = floor(x);
  return whole * (1.0 - 2.0 * a) + clamp(x - whole - a, 0.0, 1.0 - 2.0 * a);
}

// Integral from 0 to y (in rows) of the brick part of the even rows (odd = 0.0) or of the odd
// rows (odd = 1.0): rows repeat every 2, each brick part 1 - 2b high.
float brickColumnIntegral(float y, float b, float odd) {
  float pairs = floor(0.5 * y), f = y - 2.0 * pairs;  // f in [0, 2): row 0 even, row 1 odd
  float inRow = clamp(f - odd, 0.0, 1.0);
  return pairs * (1.0 - 2.0 * b) + clamp(inRow - b, 0.0, 1.0 - 2.0 * b);
}

// The average of a row's bricks over [x - w/2, x + w/2]; a width under float resolution
// point-samples.
float brickRowAverage(float x, float w, float a) {
  if (w < 1.0e-4) {
    float f = fract(x);
    return min(f, 1.0 - f) < a ? 0.0 : 1.0;
  }
  return (brickRowIntegral(x + 0.5 * w, a) - brickRowIntegral(x - 0.5 * w, a)) / w;
}

// The exact average over the footprint's axis-aligned box: the fraction of its v extent in the
// even rows' bricks times the even rows' average along u, plus the same for the odd rows
// (shifted by half a brick). Coordinates are reduced first (v mod 2 rows, u mod 1 brick), so
// the integrals' differences keep their precision.
float bricksBox(Material m, TexCoord tc, Footprint fp) {
  float columns = m.params.z, mortar = m.params.w;
  float a = 0.25 * mortar, b = 0.5 * mortar;
  vec2 w = min(clampTexCoord(uvWidth(fp) * vec2(columns, 2.0 * columns)), vec2(1.0e4));
  float u = mod(tc.uv.x * columns, 1.0), v = mod(tc.uv.y * (2.0 * columns), 2.0);
  vec2 rows;  // the fractions of the v extent in even and in odd rows' bricks
  if (w.y < 1.0e-4) {
    float f = fract(v);
    float brick = min(f, 1.0 - f) < b ? 0.0 : 1.0;
    rows = v < 1.0 ? vec2(brick, 0.0) : vec2(0.0, brick);
  } else {
    float v0 = v - 0.5 * w.y, v1 = v + 0.5 * w.y;
    rows = vec2(brickColumnIntegral(v1, b, 0.0) - brickColumnIntegral(v0, b, 0.0),
                brickColumnIntegral(v1, b, 1.0) - brickColumnIntegral(v0, b, 1.0)) / w.y;
  }
  float brick = rows.x * brickRowAverage(u, w.x, a) + rows.y * brickRowAverage(u - 0.5, w.x, a);
  return clamp(1.0 - brick, 0.0, 1.0);
}

// Rows a footprint step (duv, ds) spans: where a long footprint is split into probes (box).
float bricksCells(Material m, vec2 duv, vec3 ds) { return length(duv * vec2(m.params.z, 2.0 * m.params.z)); }
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_BRICKS_GLSL
