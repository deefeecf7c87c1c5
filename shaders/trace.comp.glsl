// raytex kernel: one primary ray per pixel through a pinhole camera, closest hit
// among analytic spheres and planes, texture lookup, Phong shading with shadow rays.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "common.h"

layout(local_size_x = WORKGROUP_X, local_size_y = WORKGROUP_Y) in;

// Specialisation: the texture kinds present (absent kinds compile out) and the output.
layout(constant_id = SPEC_TEXTURE_KINDS) const uint TEXTURE_KINDS = 0xFFFFFFFFu;
layout(constant_id = SPEC_OUTPUT_MODE) const uint OUTPUT_MODE = OUTPUT_SHADED;

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
#include "textures.glsl"
#include "intersect.glsl"
#include "shading.glsl"

// Unit direction of the primary ray through `film` (pixel units, row 0 at the top).
vec3 primaryRay(vec2 film) {
  vec2 ndc = vec2(film.x / float(frame.width) * 2.0 - 1.0, 1.0 - film.y / float(frame.height) * 2.0);
  return normalize(frame.cameraForward.xyz + ndc.x * frame.cameraRight.xyz + ndc.y * frame.cameraUp.xyz);
}

// Linear radiance along one primary ray.
vec3 radiance(vec3 origin, vec3 dir) {
  Hit hit = closestHit(origin, dir);
  if (hit.kind == HIT_NONE) return frame.background.rgb;
  Surface s = surfaceAt(hit, origin, dir);
  Material m = materials[s.material];
  return shade(s, m, textureColor(m, s.tc), -dir);
}

// Debug outputs at the pixel centre: texture coordinates or texture colour, HIT_* in alpha.
vec4 debugOutput(vec3 origin, vec3 dir) {
  Hit hit = closestHit(origin, dir);
  if (hit.kind == HIT_NONE) return vec4(0.0);
  Surface s = surfaceAt(hit, origin, dir);
  Material m = materials[s.material];
  if (OUTPUT_MODE == OUTPUT_ALBEDO) return vec4(textureColor(m, s.tc), float(hit.kind));
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
        sum += radiance(origin, primaryRay(vec2(pixel) + (vec2(sx, sy) + 0.5) / float(n)));
    result = vec4(sum / float(n * n), 1.0);
  } else {
    result = debugOutput(origin, primaryRay(vec2(pixel) + 0.5));
  }
  imageStore(outputImage, ivec2(pixel), result);
}
