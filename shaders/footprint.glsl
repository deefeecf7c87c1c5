// Texture footprints from ray differentials (compute shaders have no dFdx on lavapipe):
// the rays through the neighbouring sample positions are intersected with the tangent
// plane at the hit (pbrt's ComputeDifferentials: exact on planes, first order on spheres),
// and the mapping's derivatives carry dp/dx, dp/dy into texture space.
#ifndef RAYTEX_FOOTPRINT_GLSL
#define RAYTEX_FOOTPRINT_GLSL

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

// The mapping of the hit's shape at the surface s; with the surface steps dpdx, dpdy also its
// footprint (mapping.glsl).
TexCoord texCoordAt(Hit hit, Surface s, vec3 dpdx, vec3 dpdy, out Footprint fp) {
  if (hit.kind == HIT_PLANE) return planeTexCoord(planeAt(hit.index), s.p, dpdx, dpdy, fp);
  return sphereTexCoord(sphereAt(hit.index), s.outward, dpdx, dpdy, fp);
}

// Texture coordinates of the surface point p + dp (dp in the tangent plane at the hit):
// exact on planes; on spheres the point is projected back onto the sphere.
TexCoord texCoordNear(Hit hit, vec3 p, vec3 dp) {
  if (hit.kind == HIT_PLANE) return planeTexCoord(planeAt(hit.index), p + dp);
  Sphere sp = sphereAt(hit.index);
  return sphereTexCoord(sp, normalize(p + dp - sp.centerRadius.xyz), SPHERE_LAT_LONG);
}

// The texture coordinate and footprint of the sample at film position `film` (pixel units)
// whose neighbours lie `spacing` pixels to the right and below; also returns the surface
// steps dpdx, dpdy.
TexCoord footprintAt(Hit hit, Surface s, vec3 o, vec2 film, float spacing, out Footprint fp, out vec3 dpdx,
                     out vec3 dpdy) {
  dpdx = tangentPlaneOffset(o, s.p, s.n, primaryRayUnnormalized(film + vec2(spacing, 0.0)));
  dpdy = tangentPlaneOffset(o, s.p, s.n, primaryRayUnnormalized(film + vec2(0.0, spacing)));
  return texCoordAt(hit, s, dpdx, dpdy, fp);
}

#endif  // RAYTEX_FOOTPRINT_GLSL
