// raytex kernel: one primary ray per pixel through a pinhole camera, closest hit
// among analytic spheres and planes, texture lookup, Phong shading with shadow rays.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "common.h"

layout(local_size_x = WORKGROUP_X, local_size_y = WORKGROUP_Y) in;

// Specialisation: the texture kinds present (absent kinds compile out) and the output.
layout(constant_id = SPEC_TEXTURE_KINDS) const uint TEXTURE_KINDS = 0xFFFFFFFFu;
layout(constant_id = SPEC_OUTPUT_MODE) const uint OUTPUT_MODE = OUTPUT_SHADED;
layout(constant_id = SPEC_TEXTURE_FILTER) const uint TEXTURE_FILTER = FILTER_POINT;

layout(binding = BINDING_OUTPUT, rgba32f) uniform writeonly image2D outputImage;
layout(std140, binding = BINDING_FRAME) uniform FrameBlock { Frame frame; };
layout(std430, binding = BINDING_SPHERES) readonly buffer SphereBlock { Sphere spheres[]; };
layout(std430, binding = BINDING_PLANES) readonly buffer PlaneBlock { Plane planes[]; };
layout(std430, binding = BINDING_MATERIALS) readonly buffer MaterialBlock { Material materials[]; };
layout(std430, binding = BINDING_LIGHTS) readonly buffer LightBlock { Light lights[]; };
layout(std140, binding = BINDING_NOISE) uniform NoiseBlock { NoiseTable noiseTable; };
layout(binding = BINDING_IMAGES) uniform sampler2DArray images;

#include "noise.glsl"
#include "mapping.glsl"
#include "intersect.glsl"
#include "shading.glsl"
#include "camera.glsl"
#include "footprint.glsl"
#include "textures.glsl"

// Most probes an anisotropic footprint is split into (FILTER_BOX, closed-form kinds).
const uint MAX_PROBES = 8u;

// The texture colour at a hit. With FILTER_BOX, the average over the footprint of the
// sample at `film` whose neighbours lie `spacing` pixels away. A grazing footprint is long
// and thin, and one box around its centre is a poor fit (perspective stretches its far
// end), so closed-form kinds split it into K probes along its long screen axis, each with
// its own exact position on the surface and 1/K of the length (anisotropic filtering).
vec3 albedoAt(Hit hit, Surface s, Material m, vec3 origin, vec2 film, float spacing) {
  Footprint fp = Footprint(vec2(0.0), vec2(0.0), vec3(0.0), vec3(0.0));
  if (TEXTURE_FILTER == FILTER_POINT) return textureColor(m, s.tc, fp);
  vec3 dpdx, dpdy;
  fp = footprintAt(hit, s, origin, film, spacing, dpdx, dpdy);
  if (!hasClosedFormFilter(m.textureKind)) return textureColor(m, s.tc, fp);
  float lx = length(dpdx), ly = length(dpdy);
  bool alongX = lx >= ly;
  float ratio = alongX ? lx / max(ly, 1.0e-30) : ly / max(lx, 1.0e-30);
  uint k = uint(clamp(ceil(ratio), 1.0, float(MAX_PROBES)));
  if (k == 1u) return textureColor(m, s.tc, fp);
  if (alongX) {
    fp.duvdx /= float(k);
    fp.dsdx /= float(k);
  } else {
    fp.duvdy /= float(k);
    fp.dsdy /= float(k);
  }
  float sum = 0.0;
  for (uint i = 0u; i < k; ++i) {
    float f = ((float(i) + 0.5) / float(k) - 0.5) * spacing;
    vec3 dp = tangentPlaneOffset(origin, s.p, s.n, primaryRay(film + (alongX ? vec2(f, 0.0) : vec2(0.0, f))));
    sum += filteredBlend(m, texCoordNear(hit, s.p, dp), fp);
  }
  return mix(m.color1.rgb, m.color2.rgb, sum / float(k));
}

// Linear radiance of the sample at `film` (pixel units); `spacing` between samples.
vec3 radiance(vec3 origin, vec2 film, float spacing) {
  vec3 dir = primaryRay(film);
  Hit hit = closestHit(origin, dir);
  if (hit.kind == HIT_NONE) return frame.background.rgb;
  Surface s = surfaceAt(hit, origin, dir);
  Material m = materials[s.material];
  vec3 albedo = albedoAt(hit, s, m, origin, film, spacing);
  return shade(s, m, albedo, -dir);
}

// Debug outputs at the pixel centre: texture coordinates or texture colour, HIT_* in alpha.
vec4 debugOutput(vec3 origin, vec2 film) {
  vec3 dir = primaryRay(film);
  Hit hit = closestHit(origin, dir);
  if (hit.kind == HIT_NONE) return vec4(0.0);
  Surface s = surfaceAt(hit, origin, dir);
  Material m = materials[s.material];
  if (OUTPUT_MODE == OUTPUT_ALBEDO)
    return vec4(albedoAt(hit, s, m, origin, film, 1.0), float(hit.kind));
  bool solid = m.textureKind != TEX_IMAGE && m.textureKind != TEX_CHECKER && m.textureKind != TEX_NONE;
  return vec4(solid ? s.tc.solid : vec3(s.tc.uv, 0.0), float(hit.kind));
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= frame.width || pixel.y >= frame.height) return;
  vec3 origin = frame.eye.xyz;
  vec4 result;
  if (OUTPUT_MODE == OUTPUT_SHADED) {
    // N x N stratified samples at the centres of the sub-pixel cells, box filtered.
    uint n = max(frame.samplesPerSide, 1u);
    vec3 sum = vec3(0.0);
    for (uint sy = 0u; sy < n; ++sy)
      for (uint sx = 0u; sx < n; ++sx)
        sum += radiance(origin, vec2(pixel) + (vec2(sx, sy) + 0.5) / float(n), 1.0 / float(n));
    result = vec4(sum / float(n * n), 1.0);
  } else {
    result = debugOutput(origin, vec2(pixel) + 0.5);
  }
  imageStore(outputImage, ivec2(pixel), result);
}
