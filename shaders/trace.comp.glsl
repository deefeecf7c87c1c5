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

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= frame.width || pixel.y >= frame.height) return;

  // Through the pixel's centre; row 0 at the top.
  vec2 ndc = vec2((float(pixel.x) + 0.5) / float(frame.width) * 2.0 - 1.0,
                  1.0 - (float(pixel.y) + 0.5) / float(frame.height) * 2.0);
  vec3 origin = frame.eye.xyz;
  vec3 dir = normalize(frame.cameraForward.xyz + ndc.x * frame.cameraRight.xyz +
                       ndc.y * frame.cameraUp.xyz);

  Hit hit = closestHit(origin, dir);
  vec4 result;
  if (hit.kind == HIT_NONE) {
    result = OUTPUT_MODE == OUTPUT_SHADED ? vec4(frame.background.rgb, 1.0) : vec4(0.0);
  } else {
    Surface s = surfaceAt(hit, origin, dir);
    Material m = materials[s.material];
    vec3 albedo = textureColor(m, s.tc);
    if (OUTPUT_MODE == OUTPUT_COORDS) {
      bool solid = m.textureKind != TEX_IMAGE && m.textureKind != TEX_CHECKER &&
                   m.textureKind != TEX_NONE;
      result = vec4(solid ? s.tc.solid : vec3(s.tc.uv, 0.0), float(hit.kind));
    } else if (OUTPUT_MODE == OUTPUT_ALBEDO) {
      result = vec4(albedo, float(hit.kind));
    } else {
      result = vec4(shade(s, m, albedo, -dir), 1.0);
    }
  }
  imageStore(outputImage, ivec2(pixel), result);
}
