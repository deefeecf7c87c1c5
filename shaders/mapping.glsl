// Texture coordinates of the two shapes (course notes eqs 1-9) with the object's texture
// placement (docs/textures.md, "Texture placement") and, in the box-filtered module, their
// derivatives along the surface steps of a sample's footprint. The CPU double-precision
// oracle is host/reference/mapping.cpp; keep the two in step.
#ifndef RAYTEX_MAPPING_GLSL
#define RAYTEX_MAPPING_GLSL

#define MAPPING_PI 3.14159265358979323846

// Texture coordinates and phases clamped to +-TEXCOORD_LIMIT (common.h) stay finite.
float clampTexCoord(float x) { return clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }
vec2 clampTexCoord(vec2 x) { return clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }
vec3 clampTexCoord(vec3 x) { return clamp(x, -TEXCOORD_LIMIT, TEXCOORD_LIMIT); }

struct TexCoord {
  vec2 uv;      // 2D coordinate in [0,1]: u across, v up the image
  vec2 tile;    // index of the repeated tile, the floors of the unwrapped (u, v) (planes: mod 4096)
  vec3 solid;   // solid-texture coordinate: plane p' / s, sphere (n' + 1) / 2s, plus tex_offset
  vec2 image;   // image lookup (column, row) in [0,1], row 0 at the top (docs/textures.md)
  vec2 imageTile;  // the floors of the unwrapped image lookup (imageTile + image)
  bool clampV;  // image lookups must not wrap in v (the sphere's poles)
};

#ifdef RAYTEX_FILTER_BOX
// Texture-space derivatives for one sample step in x and in y.
struct Footprint {
  vec2 duvdx, duvdy;        // of (u + tile): one texture tile is 1
  vec2 dimagedx, dimagedy;  // of the image lookup
  vec3 dsdx, dsdy;          // of the solid coordinate
};
#endif

// v rotated by the unit quaternion q (xyz, w): the identity (0, 0, 0, 1) returns v exactly.
// TEXTURE_PLACEMENT (a specialisation constant, declared by the kernel) false: no object is
// turned (nor a sphere scaled or offset), and the placement compiles to nothing.
vec3 rotateByQuaternion(vec4 q, vec3 v) {
  if (!TEXTURE_PLACEMENT) return v;
  return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

// Plane x.n = d with the host-built placed frame t, b (Plane.tangentScale.xyz,
// Plane.binormal.xyz), image axes and tex_scale s (Plane.tangentScale.w):
//   o' = d n (6);  u_p = (p - o').t, v_p = (p - o').b (1);
//   uv = u_p/s - floor(u_p/s), v_p/s - floor(v_p/s) (2)  -- floor, never int();
//   tile = the floors (tile + uv is the unwrapped coordinate); solid = R^-1 p / s.
// p is relative to the camera, like every GPU position: u_p = (p_abs - o').t = (p + eye).t
// (o' = d n is orthogonal to t), and the host folds eye.t/s and tex_offset into pl.uvOffset
// (its fraction in xy, its integer part mod 4096 in zw: the checkers need only the tile's
// parity); the image lookup is formed alike from its own axes, its offset reduced mod 1 on
// the host, so it is seamless however far the camera is and however the axes are turned.
// A tiny s (the host keeps it >= the smallest normal float) overflows p / s to infinity, and
// floor and fract of infinity are NaN: the quotients are clamped to +-TEXCOORD_LIMIT.
TexCoord planeTexCoord(Plane pl, vec3 p) {
  float s = pl.tangentScale.w;
  vec2 st = clampTexCoord(vec2(dot(p, pl.tangentScale.xyz), dot(p, pl.binormal.xyz)) / s) + pl.uvOffset.xy;
  TexCoord tc;
  vec2 cell = floor(st);
  tc.tile = cell + pl.uvOffset.zw;
  tc.uv = st - cell;
  tc.solid = clampTexCoord(rotateByQuaternion(pl.texRotation, p) / s) + pl.solidOffset.xyz;
  vec2 image = clampTexCoord(vec2(dot(p, pl.imageRight.xyz), dot(p, pl.imageDown.xyz)) / s) +
               vec2(pl.imageRight.w, pl.imageDown.w);
  tc.imageTile = floor(image);
  tc.image = image - tc.imageTile;
  tc.clampV = false;
  return tc;
}

#ifdef RAYTEX_FILTER_BOX
// The plane's mapping at p and its derivatives along the surface steps dpdx, dpdy (linear:
// the mapping of each step without the offsets).
TexCoord planeTexCoord(Plane pl, vec3 p, vec3 dpdx, vec3 dpdy, out Footprint fp) {
  float invScale = 1.0 / pl.tangentScale.w;
  fp.duvdx = vec2(dot(dpdx, pl.tangentScale.xyz), dot(dpdx, pl.binormal.xyz)) * invScale;
  fp.duvdy = vec2(dot(dpdy, pl.tangentScale.xyz), dot(dpdy, pl.binormal.xyz)) * invScale;
  fp.dimagedx = vec2(dot(dpdx, pl.imageRight.xyz), dot(dpdx, pl.imageDown.xyz)) * invScale;
  fp.dimagedy = vec2(dot(dpdy, pl.imageRight.xyz), dot(dpdy, pl.imageDown.xyz)) * invScale;
  fp.dsdx = rotateByQuaternion(pl.texRotation, dpdx) * invScale;
  fp.dsdy = rotateByQuaternion(pl.texRotation, dpdy) * invScale;
  return planeTexCoord(pl, p);
}
#endif

// Unit outward normal n at a sphere hit, turned into the texture's frame: n' = R^-1 n.
// phi = atan2(n'_z, n'_x), theta = asin(n'_y) (7); u = (phi + pi) / 2pi, v = (theta + pi/2) / pi
// (8), divided by tex_scale s and offset, then wrapped; solid = (n' + 1) / 2s + offset (9).
// atan(0, 0) is undefined in GLSL: at the poles phi = 0 (u = 0.5).
// theta is evaluated as atan(n_y, |n_xz|), which equals asin(n_y) for a unit n but
// is well conditioned everywhere and cannot go NaN when rounding pushes |n_y| past 1
// (no clamp needed). Lavapipe's asin is off by up to 2e-4 rad for
// |n_y| > 0.5 (0.13 texel of a 1024-row image, visible at sharp image edges); the
// atan form agrees with the double asin of host/reference/mapping.cpp to ~1e-7.
// latLong false (a constant: no sphere's kind reads uv) leaves uv at 0 and skips the atans.
// While sp.clampV (s = 1, no v offset) v stays in [0, 1] for the poles' clamp.
TexCoord sphereTexCoord(Sphere sp, vec3 n, bool latLong) {
  vec3 m = rotateByQuaternion(sp.texRotation, n);
  TexCoord tc;
  tc.uv = vec2(0.0);
  tc.tile = vec2(0.0);
  if (latLong) {
    float phi = (m.x == 0.0 && m.z == 0.0) ? 0.0 : atan(m.z, m.x);
    float theta = atan(m.y, length(m.xz));
    tc.uv = vec2((phi + float(MAPPING_PI)) / float(2.0 * MAPPING_PI),
                 (theta + float(0.5 * MAPPING_PI)) / float(MAPPING_PI));
    if (TEXTURE_PLACEMENT) {
      vec2 unwrapped = clampTexCoord(tc.uv / sp.solidOffset.w) + vec2(sp.uOffset, sp.vOffset);
      tc.tile = floor(unwrapped);
      if (sp.clampV != 0u) tc.tile.y = 0.0;
      tc.uv = unwrapped - tc.tile;
    }
  }
  tc.solid = (m + 1.0) * 0.5;
  if (TEXTURE_PLACEMENT) tc.solid = clampTexCoord(tc.solid / sp.solidOffset.w) + sp.solidOffset.xyz;
  tc.image = vec2(1.0) - tc.uv;
  tc.imageTile = -tc.tile;  // 1 - (tile + uv)
  tc.clampV = !TEXTURE_PLACEMENT || sp.clampV != 0u;
  return tc;
}

#ifdef RAYTEX_FILTER_BOX
// The sphere's mapping at the outward normal n and its derivatives along the surface steps
// dpdx, dpdy (first order: dn = the step's tangential part / r).
TexCoord sphereTexCoord(Sphere sp, vec3 n, vec3 dpdx, vec3 dpdy, out Footprint fp) {
  vec3 m = rotateByQuaternion(sp.texRotation, n);
  float invScale = TEXTURE_PLACEMENT ? 1.0 / sp.solidOffset.w : 1.0;
  float r = sp.centerRadius.w;
  vec3 dmdx = rotateByQuaternion(sp.texRotation, (dpdx - n * dot(n, dpdx)) / r);
  vec3 dmdy = rotateByQuaternion(sp.texRotation, (dpdy - n * dot(n, dpdy)) / r);
  // u = (atan2(m_z, m_x) + pi) / 2pi, v = (asin(m_y) + pi/2) / pi, differentiated; both
  // blow up at the poles, where the widths grow and the filter returns the average.
  float rho2 = max(m.x * m.x + m.z * m.z, 1.0e-12);
  fp.duvdx = vec2((m.x * dmdx.z - m.z * dmdx.x) / (2.0 * 3.14159265 * rho2), dmdx.y / (3.14159265 * sqrt(rho2))) * invScale;
  fp.duvdy = vec2((m.x * dmdy.z - m.z * dmdy.x) / (2.0 * 3.14159265 * rho2), dmdy.y / (3.14159265 * sqrt(rho2))) * invScale;
  fp.dimagedx = -fp.duvdx;  // image = 1 - uv
  fp.dimagedy = -fp.duvdy;
  fp.dsdx = dmdx * (0.5 * invScale);  // solid = (n' + 1) / 2s
  fp.dsdy = dmdy * (0.5 * invScale);
  return sphereTexCoord(sp, n, SPHERE_LAT_LONG);
}
#endif

#endif  // RAYTEX_MAPPING_GLSL
