// The coverage filter's main kernel (FILTER_COVERAGE, EDGE_FLAGS): which pixels an edge may
// cross, found while the pixel is traced, after Amanatides' cones ("Ray tracing with cones",
// SIGGRAPH 1984). Every sphere a primary ray tests is measured against the pixel's cone: where
// its silhouette passes within the pixel (the distance of its centre from the ray's line within
// the cone's radius of r) and in front of the hit, it is the pixel's edge object, the nearest
// such edge if there are several; so is a plane whose horizon passes within the pixel, where
// the ray sees the plane or nothing, and the line where the plane the ray sees meets the next
// plane along it (a crease, EDGE_CREASE). Every sphere a shadow ray tests is measured alike
// against the bundle of shadow rays from the pixel's footprint to the light. The main kernel lists the
// pixels with an edge object or a shadow's edge (BINDING_EDGE_LIST) for the edge pass
// (coverage.glsl). Spheres a tree walk or a list skips are not measured: an edge along such a
// sphere's box, or just outside a shadow list's cell, is missed (docs/accuracy.md).
//
// Needs (declared by the including kernel): EDGE_FLAGS, primaryRay.
#ifndef RAYTEX_EDGE_FLAGS_GLSL
#define RAYTEX_EDGE_FLAGS_GLSL

// Set by startEdgeFlags where EDGE_FLAGS, and read only there: no initialisers, which would be
// stores every invocation of every kernel makes.
float edgeCone;     // the primary ray's cone: its radius at unit distance
uint edgeObject;    // the object (EDGE_ID) whose edge passes nearest within the pixel
float edgeMargin;   // its distance from the ray in cone radii (below 1: within the pixel)
float edgeNear;     // how far along the ray its edge begins
bool edgeShadow;    // a shadow ray passed within its bundle's radius of a sphere's edge
float shadowRadius; // the radius of the bundle of shadow rays at the surface (albedoAt)
float shadowLength; // the current shadow ray's distance to its light (visibleShare)
float planeNearT;   // the primary ray's two nearest plane hits, and their planes
float planeNextT;
uint planeNear;
uint planeNext;

// |distance of the sphere's centre from the line o + t d (unit d) - r| in units of `radius`
// (from the discriminant, without a square root: |r^2 - h^2| against radius (2r + radius));
// `along`: how far along the line the centre lies.
float sphereMargin(vec3 o, vec3 d, vec4 cr, float along, float radius) {
  vec3 perp = o + along * d - cr.xyz;
  float disc = cr.w * cr.w - dot(perp, perp);
  return abs(disc) / max(radius * (2.0 * cr.w + radius), 1.0e-30);
}

// Before a primary ray is traced through `film`: its cone reaches the corners of its sample's
// cell, `spacing` pixels wide (half a diagonal of the step to the next sample, with a margin of
// 10 %).
void startEdgeFlags(vec2 film, float spacing) {
  if (!EDGE_FLAGS) return;
  edgeCone = 0.78 * length(primaryRay(film + vec2(spacing, 0.0)) - primaryRay(film));
  edgeObject = EDGE_NONE;
  edgeMargin = 1.0;
  edgeNear = 0.0;
  edgeShadow = false;
  shadowRadius = 0.0;
  shadowLength = 0.0;
  planeNearT = T_MAX;
  planeNextT = T_MAX;
  planeNear = 0u;
  planeNext = 0u;
}

// A primary ray from o along unit d, nearest hit so far at tMax, tests sphere `index`.
void notePrimarySphere(vec3 o, vec3 d, vec4 cr, uint index, float tMax) {
  if (!EDGE_FLAGS) return;
  float along = dot(cr.xyz - o, d);
  float margin = sphereMargin(o, d, cr, along, edgeCone * max(along, 0.0));
  if (margin < edgeMargin && along > 0.0 && along - cr.w < tMax) {
    edgeMargin = margin;
    edgeObject = HIT_SPHERE << EDGE_KIND_SHIFT | index;
    edgeNear = along - cr.w;
  }
}

// A primary ray from o along unit d tests plane `index`: its horizon lies where d meets the
// plane at 0; its hit, if among the two nearest, may be a crease's side.
void notePrimaryPlane(vec3 o, vec3 d, vec4 normalDistance, uint index) {
  if (!EDGE_FLAGS) return;
  float margin = abs(dot(normalDistance.xyz, d)) / max(edgeCone, 1.0e-30);
  if (margin < edgeMargin) {
    edgeMargin = margin;
    edgeObject = HIT_PLANE << EDGE_KIND_SHIFT | index;
    edgeNear = T_MAX;
  }
  float t = intersectPlane(o, d, normalDistance, 0.0, T_MAX);
  if (t > 0.0 && t < planeNextT) {
    bool nearest = t < planeNearT;
    planeNextT = nearest ? planeNearT : t;
    planeNext = nearest ? planeNear : index;
    planeNearT = nearest ? t : planeNearT;
    planeNear = nearest ? index : planeNear;
  }
}

// The normal (unnormalised) of the plane through the eye o that holds the line where planes a
// and b meet: the rays on its either side meet a or b first (for rays that meet both ahead,
// t_a < t_b is linear in the ray: h_a (n_b . d) < h_b (n_a . d), h the eye's height over each).
vec3 creaseNormal(vec3 o, vec4 a, vec4 b) {
  return (a.w - dot(a.xyz, o)) * b.xyz - (b.w - dot(b.xyz, o)) * a.xyz;
}

// The primary ray's hit on the nearest plane: the crease with the next plane along the ray, if
// it passes within the pixel and nearer the ray than the edge found so far.
void notePrimaryCrease(vec3 o, vec3 d) {
  if (planeNextT == T_MAX) return;
  vec3 m = creaseNormal(o, planeAt(planeNear).normalDistance, planeAt(planeNext).normalDistance);
  float margin = abs(dot(m, d)) / max(length(m) * edgeCone, 1.0e-30);
  if (margin < edgeMargin) {
    edgeMargin = margin;
    edgeObject = EDGE_CREASE << EDGE_KIND_SHIFT | planeNear << EDGE_PLANE_SHIFT | planeNext;
  }
}

// After the primary ray's closest hit: an edge hidden behind the hit surface is none (a horizon
// shows only where the ray sees its plane or nothing); on a plane, the crease may be the edge.
void endPrimaryEdges(vec3 o, vec3 d, Hit hit) {
  if (!EDGE_FLAGS) return;
  bool itself = edgeObject == (hit.kind << EDGE_KIND_SHIFT | hit.index);
  if (edgeObject != EDGE_NONE && !itself && hit.kind != HIT_NONE && !(edgeNear < hit.t)) {
    edgeObject = EDGE_NONE;
    edgeMargin = 1.0;
  }
  if (hit.kind == HIT_PLANE && hit.index == planeNear) notePrimaryCrease(o, d);
}

// A shadow ray from o along unit l (shadowLength to the light) tests a sphere: the bundle's
// radius shrinks linearly to 0 at the light.
void noteShadowSphere(vec3 o, vec3 l, vec4 cr) {
  if (!EDGE_FLAGS) return;
  float along = dot(cr.xyz - o, l);
  float radius = 1.1 * shadowRadius * max(1.0 - along / shadowLength, 0.0);
  if (along > 0.0 && along < shadowLength && sphereMargin(o, l, cr, along, radius) < 1.0) edgeShadow = true;
}

#endif  // RAYTEX_EDGE_FLAGS_GLSL
