// Texture footprints from ray differentials (compute shaders have no dFdx on lavapipe):
// the rays through the neighbouring sample positions are intersected with the tangent
// plane at the hit (pbrt's ComputeDifferentials: exact on planes, first order on spheres),
// and the mapping's derivatives carry dp/dx, dp/dy into texture space.
#ifndef RAYTEX_FOOTPRINT_GLSL
#define RAYTEX_FOOTPRINT_GLSL

// Texture-space derivatives for one sample step in x and in y.
struct Footprint {
  vec2 duvdx, duvdy;  // of (u + tile): one texture tile is 1
  vec3 dsdx, dsdy;    // of the solid coordinate
};

// A differential ray parallel to the surface has no intersection: treat it as a huge
// footprint, so filtered textures fall back to their average instead of aliasing.
const float FOOTPRINT_MAX = 1.0e8;

// Where the ray o + t dir meets the tangent plane (p, n), relative to p.
vec3 tangentPlaneOffset(vec3 o, vec3 p, vec3 n, vec3 dir) {
  float t = dot(n, p - o) / dot(n, dir);
  vec3 offset = o + t * dir - p;
  return (abs(t) < FOOTPRINT_MAX) ? offset : vec3(FOOTPRINT_MAX);
}

// Per-axis filter widths (pbrt: the larger of the x and y derivatives).
vec2 uvWidth(Footprint f) { return min(max(abs(f.duvdx), abs(f.duvdy)), vec2(FOOTPRINT_MAX)); }
vec3 solidWidth(Footprint f) { return min(max(abs(f.dsdx), abs(f.dsdy)), vec3(FOOTPRINT_MAX)); }

// Texture coordinates of the surface point p + dp (dp in the tangent plane at the hit):
// exact on planes; on spheres the point is projected back onto the sphere.
TexCoord texCoordNear(Hit hit, vec3 p, vec3 dp) {
  if (hit.kind == HIT_PLANE) return planeTexCoord(planeAt(hit.index), p + dp);
  vec4 cr = sphereAt(hit.index).centerRadius;
  return sphereTexCoord(normalize(p + dp - cr.xyz), SPHERE_LAT_LONG);
}

// Texture-space derivatives of a surface step dp at the hit.
void textureDerivatives(Hit hit, Surface s, vec3 dp, out vec2 duv, out vec3 ds) {
  if (hit.kind == HIT_PLANE) {
    Plane pl = planeAt(hit.index);
    float invScale = 1.0 / pl.tangentScale.w;
    duv = vec2(dot(dp, pl.tangentScale.xyz), dot(dp, pl.binormal.xyz)) * invScale;
    ds = dp * invScale;
  } else {
    vec4 cr = sphereAt(hit.index).centerRadius;
    vec3 n = normalize(s.p - cr.xyz);  // outward, as the mapping uses
    vec3 dn = (dp - n * dot(n, dp)) / cr.w;
    // u = (atan2(n_z, n_x) + pi) / 2pi, v = (asin(n_y) + pi/2) / pi, differentiated; both
    // blow up at the poles, where the widths grow and the filter returns the average.
    float rho2 = max(n.x * n.x + n.z * n.z, 1.0e-12);
    duv = vec2((n.x * dn.z - n.z * dn.x) / (2.0 * 3.14159265 * rho2), dn.y / (3.14159265 * sqrt(rho2)));
    ds = dn * 0.5;  // solid = (n + 1) / 2
  }
}

// The footprint of the sample at film position `film` (pixel units) whose neighbours lie
// `spacing` pixels to the right and below; also returns the surface steps dpdx, dpdy.
Footprint footprintAt(Hit hit, Surface s, vec3 o, vec2 film, float spacing, out vec3 dpdx, out vec3 dpdy) {
  dpdx = tangentPlaneOffset(o, s.p, s.n, primaryRayUnnormalized(film + vec2(spacing, 0.0)));
  dpdy = tangentPlaneOffset(o, s.p, s.n, primaryRayUnnormalized(film + vec2(0.0, spacing)));
  Footprint f;
  textureDerivatives(hit, s, dpdx, f.duvdx, f.dsdx);
  textureDerivatives(hit, s, dpdy, f.duvdy, f.dsdy);
  return f;
}

#endif  // RAYTEX_FOOTPRINT_GLSL
