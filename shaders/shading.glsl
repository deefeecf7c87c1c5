// Surface reconstruction at a hit and Phong shading with hard shadows.

struct Surface {
  vec3 p;        // hit point (on the surface)
  vec3 n;        // unit normal, facing the viewer
  vec3 outward;  // unit normal, outward (the sphere mapping's)
  TexCoord tc;
  uint material;
};

Surface surfaceAt(Hit hit, vec3 o, vec3 d) {
  Surface s;
  if (hit.kind == HIT_SPHERE) {
    Sphere sp = sphereAt(hit.index);
    // Re-project onto the sphere: o + t d carries the error of t.
    // A ray through the centre of a sphere too small for float (radius 0, or r^2 below
    // the smallest float) hits at the centre itself, where normalize(0) is NaN: there
    // the sphere is a point seen head-on, so take the normal facing the ray.
    vec3 toHit = o + hit.t * d - sp.centerRadius.xyz;
    vec3 outward = dot(toHit, toHit) > 0.0 ? normalize(toHit) : -d;
    s.p = sp.centerRadius.xyz + sp.centerRadius.w * outward;
    s.tc = sphereTexCoord(sp, outward, SPHERE_LAT_LONG);  // the mapping uses the outward normal, inside or out
    s.n = outward;
    s.outward = outward;
    s.material = sp.material;
  } else {
    Plane pl = planeAt(hit.index);
    // Re-project onto the plane: removes the error of t along the normal.
    vec3 n = pl.normalDistance.xyz;
    s.p = o + hit.t * d;
    s.p -= n * (dot(n, s.p) - pl.normalDistance.w);
    s.tc = planeTexCoord(pl, s.p);
    s.n = pl.normalDistance.xyz;
    s.outward = s.n;
    s.material = pl.material;
  }
  if (dot(s.n, d) > 0.0) s.n = -s.n;  // seen from behind (plane underside, inside a sphere)
  return s;
}

// The origin of a shadow ray: p moved off the surface along n by a fixed number of float
// steps per component (Wachter and Binder, Ray Tracing Gems ch. 6), so the offset follows
// the rounding error of p at any distance from the origin; a fixed offset is too large
// near the origin and, far out, smaller than the rounding (or, scaled by |p|, larger than
// the objects: at 1e5 it lifts shadow rays over a unit sphere). Components near zero,
// where float steps are tiny, move by a small absolute amount instead.
vec3 offsetOrigin(vec3 p, vec3 n) {
  const float nearZero = 1.0 / 32.0;
  const float absoluteStep = 1.0 / 65536.0;
  const float floatSteps = 256.0;
  ivec3 steps = ivec3(floatSteps * n);
  ivec3 bits = floatBitsToInt(p);
  vec3 stepped = intBitsToFloat(ivec3(p.x < 0.0 ? bits.x - steps.x : bits.x + steps.x,
                                      p.y < 0.0 ? bits.y - steps.y : bits.y + steps.y,
                                      p.z < 0.0 ? bits.z - steps.z : bits.z + steps.z));
  return vec3(abs(p.x) < nearZero ? p.x + absoluteStep * n.x : stepped.x,
              abs(p.y) < nearZero ? p.y + absoluteStep * n.y : stepped.y,
              abs(p.z) < nearZero ? p.z + absoluteStep * n.z : stepped.z);
}

// How much of light `light` reaches the sample from o along unit l (dist away): 1 or 0 from one
// shadow ray (measured against the spheres' edges for the coverage filter: edge_flags.glsl), or,
// in the coverage filter's edge pass, the lit share of the sample's footprint (coverage.glsl).
// `passes`: as occluded's.
float visibleShare(vec3 o, vec3 l, float dist, uint light, out uint passes) {
#ifdef RAYTEX_EDGE_PASS
  return litShare(o, l, dist, light, passes);
#else
  if (EDGE_FLAGS) shadowLength = dist;
  return occluded(o, l, dist, light, passes) ? 0.0 : 1.0;
#endif
}

// Phong: ambient + per light (diffuse k_d N.L + specular k_s (R.V)^shininess) times the
// light's visible share. A texture's colour replaces k_d and also tints the ambient
// term, so the pattern stays visible in shadow. Colours are >= 0 but unbounded: a product of
// large ones overflows to infinity, and infinity times a zero channel is NaN, so each product
// that is multiplied again, and the result, are clamped to RADIANCE_LIMIT (common.h).
vec3 shade(Surface s, Material m, vec3 albedo, vec3 toEye) {
  bool textured = m.textureKind != TEX_NONE;
  vec3 color = min(frame.ambientLight.rgb * m.ambient.rgb, vec3(RADIANCE_LIMIT)) * (textured ? albedo : vec3(1.0));
  vec3 origin = offsetOrigin(s.p, s.n);
  for (uint i = 0u; i < lightCount(); ++i) {
    vec3 toLight = lightAt(i).position.xyz - s.p;
    float dist = length(toLight);
    // A hit over about 1.8e19 from the light (a plane towards its horizon) squares past the
    // float range: its distance is measured 2^64 times smaller (exact: a power of two).
    if (isinf(dist)) dist = length(toLight * exp2(-64.0)) * exp2(64.0);
    if (!(dist > 0.0)) continue;
    vec3 l = toLight / dist;
    float nDotL = dot(s.n, l);
    if (nDotL <= 0.0) continue;
    uint passes;
    float lit = visibleShare(origin, l, dist, i, passes);
    if ((SPHERE_TREE == SPHERE_TREE_NONE && SPHERE_COUNT == COUNT_FROM_FRAME) || PLANE_COUNT == COUNT_FROM_FRAME)
      countLoop(passes);
    if (!(lit > 0.0)) continue;
    vec3 r = reflect(-l, s.n);
    float rDotV = max(dot(r, toEye), 0.0);
    vec3 specular = rDotV > 0.0 ? m.specular.rgb * pow(rDotV, m.specular.w) : vec3(0.0);
    color += lit * lightAt(i).color.rgb * min(albedo * nDotL + specular, vec3(RADIANCE_LIMIT));
  }
  if (LIGHT_COUNT == COUNT_FROM_FRAME) countLoop(lightCount());
  return min(color, vec3(RADIANCE_LIMIT));
}
