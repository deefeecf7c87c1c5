// Texture coordinates of the two shapes (course notes eqs 1-9). The CPU
// double-precision oracle is host/mapping.cpp; keep the two in step.
#ifndef RAYTEX_MAPPING_GLSL
#define RAYTEX_MAPPING_GLSL

#define MAPPING_PI 3.14159265358979323846

// Texture coordinates and phases clamped to +-TEXCOORD_LIMIT (common.h) stay finite.
float clampTexCoord(float x) { return clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }
vec2 clampTexCoord(vec2 x) { return clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }
vec3 clampTexCoord(vec3 x) { return clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }

struct TexCoord {
  vec2 uv;      // 2D coordinate in [0,1]: u across, v up the image
  vec2 tile;    // plane: index of the repeated tile, floor(u_p/s), floor(v_p/s), mod 4096; sphere: 0
  vec3 solid;   // solid-texture coordinate: plane p / s, sphere (n + 1) / 2
  bool clampV;  // image lookups must not wrap in v (the sphere's poles)
};

// Plane x.n = d with the host-built frame t, b (Plane.tangentScale.xyz, Plane.binormal.xyz)
// and tex_scale s (Plane.tangentScale.w):
//   o' = d n (6);  u_p = (p - o').t, v_p = (p - o').b (1);
//   uv = u_p/s - floor(u_p/s), v_p/s - floor(v_p/s) (2)  -- floor, never int();
//   tile = the floors (tile + uv is the unwrapped coordinate); solid = p / s.
// p is relative to the camera, like every GPU position: u_p = (p_abs - o').t = (p + eye).t
// (o' = d n is orthogonal to t), and the host folds eye.t/s into pl.uvOffset (its fraction
// in xy, its integer part mod 4096 in zw: the checkers need only the tile's parity).
// A tiny s (the host keeps it >= the smallest normal float) overflows p / s to infinity, and
// floor and fract of infinity are NaN: the quotients are clamped to +-TEXCOORD_LIMIT.
TexCoord planeTexCoord(Plane pl, vec3 p) {
  vec3 t = pl.tangentScale.xyz;
  float s = pl.tangentScale.w;
  vec3 b = pl.binormal.xyz;
  vec2 st = clampTexCoord(vec2(dot(p, t), dot(p, b)) / s) + pl.uvOffset.xy;
  TexCoord tc;
  vec2 cell = floor(st);
  tc.tile = cell + pl.uvOffset.zw;
  tc.uv = st - cell;
  tc.solid = clampTexCoord(p / s) + pl.solidOffset.xyz;
  tc.clampV = false;
  return tc;
}

// Unit normal n at a sphere hit. phi = atan2(n_z, n_x), theta = asin(n_y) (7);
// u = (phi + pi) / 2pi, v = (theta + pi/2) / pi (8); solid = (n + 1) / 2 (9).
// atan(0, 0) is undefined in GLSL: at the poles phi = 0 (u = 0.5).
// theta is evaluated as atan(n_y, |n_xz|), which equals asin(n_y) for a unit n but
// is well conditioned everywhere and cannot go NaN when rounding pushes |n_y| past 1
// (no clamp needed). Measured on lavapipe: its asin is off by up to 2e-4 rad for
// |n_y| > 0.5 (0.13 texel of a 1024-row image, visible at sharp image edges); the
// atan form agrees with the double asin of host/mapping.cpp to ~1e-7.
// latLong false (a constant: no sphere's kind reads uv) leaves uv at 0 and skips the atans.
TexCoord sphereTexCoord(vec3 n, bool latLong) {
  TexCoord tc;
  tc.uv = vec2(0.0);
  if (latLong) {
    float phi = (n.x == 0.0 && n.z == 0.0) ? 0.0 : atan(n.z, n.x);
    float theta = atan(n.y, length(n.xz));
    tc.uv = vec2((phi + float(MAPPING_PI)) / float(2.0 * MAPPING_PI),
                 (theta + float(0.5 * MAPPING_PI)) / float(MAPPING_PI));
  }
  tc.tile = vec2(0.0);
  tc.solid = (n + 1.0) * 0.5;
  tc.clampV = true;
  return tc;
}

#endif  // RAYTEX_MAPPING_GLSL
