// The coverage filter's edge pass (FILTER_COVERAGE): analytic edge coverage at one ray per
// pixel, after Amanatides' cones ("Ray tracing with cones", SIGGRAPH 1984). Raytex renders
// analytic spheres and planes only, so the edges that cross a pixel have closed forms:
// - a sphere's silhouette: the distance of the sphere's centre from the primary ray's line
//   minus the radius (coverGap);
// - a plane's horizon: where the primary ray turns parallel to the plane, a straight line on the
//   film (coverGap);
// - a crease, the line where two planes meet: also straight on the film (coverGap);
// - a shadow's edge: the distance of the occluding sphere's centre from the segment from the
//   surface point to the light, minus the radius, over the pixel's footprint on the surface
//   (litShare).
// Each such gap g is negative on the covered (or shadowed) side; linearised over the pixel, the
// share of the pixel square on that side is shareBelow(g, gradient). The main kernel lists the
// pixels an edge may cross with the edge's object (edge_flags.glsl); this pass shades each
// again: the surface on the centre's side of the edge and the one across it, each at the middle
// of its part of the pixel, mixed by their shares, with every light weighted by its lit share.
// Textures keep the box filter. With N x N samples per pixel each sample is one dispatch of the
// main kernel and this pass (the progressive kernels), and "pixel" above is the sample's cell,
// 1/N of a pixel wide. Approximations (docs/accuracy.md, "The coverage filter"): two
// surfaces per pixel (the edge nearest the centre), straight edges within a pixel, the
// occluders' shares multiplied as if independent; shadows of planes, and the edges where a
// sphere cuts a plane or another sphere, not covered.
//
// Needs (declared by the including kernel): frame, sphereAt, planeAt, sphereCount, planeCount,
// primaryRayUnnormalized, intersectPlane, occluded.
#ifndef RAYTEX_COVERAGE_GLSL
#define RAYTEX_COVERAGE_GLSL

// The share of the cell (a square of side 1: the pixel, or the sample's cell in its own units,
// centred on the sample) where value + gradient . x < 0, x the offset from the centre: the area cut off by a straight edge (the
// distribution of x . n over the square is a trapezoid; this is its integral).
float shareBelow(float value, vec2 gradient) {
  float len = length(gradient);
  if (!(len > 1.0e-20)) return value < 0.0 ? 1.0 : 0.0;
  float u = -value / len;  // the edge's distance from the centre along n
  vec2 n = abs(gradient) / len;
  float a = max(n.x, n.y), b = min(n.x, n.y);
  float inner = 0.5 * (a - b), outer = 0.5 * (a + b);
  if (u <= -outer) return 0.0;
  if (u >= outer) return 1.0;
  if (u < -inner) return (u + outer) * (u + outer) / (2.0 * a * b);
  if (u > inner) return 1.0 - (outer - u) * (outer - u) / (2.0 * a * b);
  return 0.5 + u / a;
}

// The object of an EDGE_ID, and its kind (HIT_* or EDGE_CREASE).
uint edgeKind(uint id) { return id >> EDGE_KIND_SHIFT; }
uint edgeIndex(uint id) { return id & ((1u << EDGE_KIND_SHIFT) - 1u); }

// Negative where the object `id` covers the primary ray through `film` (it may still be hidden
// by a nearer one), positive where the ray passes it; 0 on its silhouette or horizon. For a
// crease: negative on one plane's side, positive on the other's.
float coverGap(uint id, vec3 o, vec2 film) {
  vec3 d = primaryRayUnnormalized(film);
  if (edgeKind(id) == EDGE_CREASE) {
    uint mask = (1u << EDGE_PLANE_SHIFT) - 1u;
    vec3 m = creaseNormal(o, planeAt((id >> EDGE_PLANE_SHIFT) & mask).normalDistance,
                          planeAt(id & mask).normalDistance);
    return dot(m, d) / (length(m) * length(d));
  }
  if (edgeKind(id) == HIT_PLANE) {
    // Linear in film: the horizon is a straight line. The ray meets the plane ahead where d . n
    // has the sign of the eye's side.
    vec4 nd = planeAt(edgeIndex(id)).normalDistance;
    return (nd.w - dot(nd.xyz, o) >= 0.0 ? -1.0 : 1.0) * dot(nd.xyz, d) / length(d);
  }
  vec4 cr = sphereAt(edgeIndex(id)).centerRadius;
  vec3 f = cr.xyz - o, u = normalize(d);
  float along = dot(f, u);
  return (along > 0.0 ? length(f - along * u) : length(f)) - cr.w;
}

// The gap's change over one sample cell, `spacing` pixels wide, along x and y (central
// differences: exact for the horizon and creases, within the silhouette's curvature for
// spheres).
vec2 coverGapGradient(uint id, vec3 o, vec2 film, float spacing) {
  float h = 0.5 * spacing;
  return vec2(coverGap(id, o, film + vec2(h, 0.0)) - coverGap(id, o, film - vec2(h, 0.0)),
              coverGap(id, o, film + vec2(0.0, h)) - coverGap(id, o, film - vec2(0.0, h)));
}

// The share of the sample's cell (`spacing` pixels wide, centred on `film`) on the centre's side
// of the edge of `id`, and a film position in the middle of each side's part (along the edge's
// normal through the centre).
float edgeSplit(uint id, vec3 o, vec2 film, float spacing, out vec2 centreSide, out vec2 farSide) {
  float g = coverGap(id, o, film);
  vec2 gradient = coverGapGradient(id, o, film, spacing);
  float len = max(length(gradient), 1.0e-20);
  vec2 n = (g < 0.0 ? gradient : -gradient) / len;  // from the centre's side towards the other
  float distance = abs(g) / len;  // in cells
  float reach = 0.5 * (abs(n.x) + abs(n.y));  // the cell's extent along n
  centreSide = film + n * (0.5 * (min(distance, reach) - reach) * spacing);
  farSide = film + n * (0.5 * (min(distance, reach) + reach) * spacing);
  float below = shareBelow(g, gradient);
  return g < 0.0 ? below : 1.0 - below;
}

// The sample being shaded: its surface steps of one pixel (set by albedoAt) and its sphere
// (set by radiance; none on a plane), which cannot shadow its own lit side.
vec3 shadeDpdx = vec3(0.0), shadeDpdy = vec3(0.0);
uint shadeSelf = 0xFFFFFFFFu;

// Distance from the sphere (centre, radius) to the segment from q to `target`: negative where
// the segment passes through it.
float segmentGap(vec3 q, vec3 target, vec4 cr) {
  vec3 d = target - q;
  float t = clamp(dot(cr.xyz - q, d) / dot(d, d), 0.0, 1.0);
  return length(cr.xyz - (q + t * d)) - cr.w;
}

// The share of the sample's footprint (shadeDpdx, shadeDpdy around o) from which the light at
// o + l * dist is visible: each sphere other than `self` blocks the share where its segment gap
// is negative (linearised over the footprint), the shares multiplied; a plane across the centre's
// segment blocks all of it. Scenes that walk a sphere tree keep the centre's answer.
// `passes`: as occluded's.
float litShare(vec3 o, vec3 l, float dist, uint light, out uint passes) {
  if (SPHERE_TREE != SPHERE_TREE_NONE) return occluded(o, l, dist, light, passes) ? 0.0 : 1.0;
  passes = 1u;  // a masked pass of the second loop (countLoop adds one)
  for (uint i = 0u; i < planeCount(); ++i) {
    ++passes;
    if (intersectPlane(o, l, planeAt(i).normalDistance, 0.0, dist) > 0.0) return 0.0;
  }
  vec3 target = o + l * dist;
  float lit = 1.0;
  for (uint i = 0u; i < sphereCount(); ++i) {
    ++passes;
    if (i == shadeSelf) continue;
    vec4 cr = sphereAt(i).centerRadius;
    float g = segmentGap(o, target, cr);
    vec2 gradient = vec2(segmentGap(o + 0.5 * shadeDpdx, target, cr) - segmentGap(o - 0.5 * shadeDpdx, target, cr),
                         segmentGap(o + 0.5 * shadeDpdy, target, cr) - segmentGap(o - 0.5 * shadeDpdy, target, cr));
    lit *= 1.0 - shareBelow(g, gradient);
  }
  return lit;
}

#endif  // RAYTEX_COVERAGE_GLSL
