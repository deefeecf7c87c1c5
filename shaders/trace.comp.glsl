// raytex kernel: one primary ray per pixel through a pinhole camera, closest hit
// among analytic spheres and planes, texture lookup, Phong shading with shadow rays.
// Built as several modules (CMakeLists.txt, add_spirv): the shaded image with point-sampled
// textures; with RAYTEX_FILTER_BOX, with textures filtered over footprints (FILTER_BOX); with
// RAYTEX_SUPERSAMPLE, N x N samples in one dispatch; with RAYTEX_DEBUG_OUTPUT, the outputs the
// tests compare with the CPU reference; with RAYTEX_AOV, the shaded image (one sample or N x N,
// point or box textures) and the passes (passes.glsl); each also with RAYTEX_SPHERE_TREE, the
// sphere tree's walks and the tile and shadow lists (intersect.glsl); with RAYTEX_EDGE_PASS
// (and RAYTEX_FILTER_BOX), the coverage filter's edge pass over the listed pixels
// (coverage.glsl).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "common.h"

layout(local_size_x = WORKGROUP_X, local_size_y = WORKGROUP_Y) in;

// Specialisation: the texture kinds on each shape (absent kinds compile out), the object and
// light counts, and the output. The defaults are the unspecialised kernel.
layout(constant_id = SPEC_SPHERE_TEXTURE_KINDS) const uint SPHERE_TEXTURE_KINDS = 0xFFFFFFFFu;
layout(constant_id = SPEC_PLANE_TEXTURE_KINDS) const uint PLANE_TEXTURE_KINDS = 0xFFFFFFFFu;
const uint TEXTURE_KINDS = SPHERE_TEXTURE_KINDS | PLANE_TEXTURE_KINDS;
layout(constant_id = SPEC_SPHERE_COUNT) const uint SPHERE_COUNT = COUNT_FROM_FRAME;
layout(constant_id = SPEC_PLANE_COUNT) const uint PLANE_COUNT = COUNT_FROM_FRAME;
layout(constant_id = SPEC_LIGHT_COUNT) const uint LIGHT_COUNT = COUNT_FROM_FRAME;
layout(constant_id = SPEC_IMAGE_COUNT) const uint IMAGE_COUNT = MAX_IMAGES;
layout(constant_id = SPEC_OUTPUT_MODE) const uint OUTPUT_MODE = OUTPUT_SHADED;
// A constant, not a uniform: on lavapipe a loop with a runtime bound around the whole shading
// code is far slower (docs/performance.md, "Specialised against unspecialised pipelines").
layout(constant_id = SPEC_SAMPLES_PER_SIDE) const uint SAMPLES_PER_SIDE = 1u;
layout(constant_id = SPEC_PROGRESSIVE) const bool PROGRESSIVE = false;
layout(constant_id = SPEC_BAKED) const bool BAKED = false;
layout(constant_id = SPEC_TEXTURE_PLACEMENT) const bool TEXTURE_PLACEMENT = true;
layout(constant_id = SPEC_BAKED_MATERIAL_COUNT) const uint BAKED_MATERIAL_COUNT = 1u;
layout(constant_id = SPEC_SPHERE_TREE) const uint SPHERE_TREE = SPHERE_TREE_NONE;
layout(constant_id = SPEC_LOOP_BUDGET) const uint LOOP_BUDGET = 0u;
layout(constant_id = SPEC_TILE_LISTS) const bool TILE_LISTS = false;
layout(constant_id = SPEC_TILE_ORDER) const bool TILE_ORDER = false;
layout(constant_id = SPEC_SHADOW_LISTS) const bool SHADOW_LISTS = false;
#ifdef RAYTEX_AOV
layout(constant_id = SPEC_PASS_MASK) const uint PASS_MASK = 0u;
#endif
// FILTER_COVERAGE: the box kernel also lists the pixels an edge may cross (edge_flags.glsl).
layout(constant_id = SPEC_TEXTURE_FILTER) const uint TEXTURE_FILTER = FILTER_POINT;
layout(constant_id = SPEC_IMAGE_FILTER) const uint IMAGE_FILTER = IMAGE_FILTER_ANISOTROPIC;
#ifdef RAYTEX_EDGE_PASS
const bool EDGE_FLAGS = false;
#else
const bool EDGE_FLAGS = TEXTURE_FILTER == FILTER_COVERAGE;
#endif

layout(std430, binding = BINDING_OUTPUT) writeonly buffer OutputBlock { vec4 outputPixels[]; };
layout(std140, binding = BINDING_FRAME) uniform FrameBlock { Frame frameBlock; };
layout(std140, binding = BINDING_SPHERES) uniform SphereBlock { Sphere sphereBlock[MAX_UNIFORM_SPHERES]; };
layout(std140, binding = BINDING_PLANES) uniform PlaneBlock { Plane planeBlock[MAX_PLANES]; };
layout(std140, binding = BINDING_MATERIALS) uniform MaterialBlock { Material materials[MAX_MATERIALS]; };
layout(std140, binding = BINDING_LIGHTS) uniform LightBlock { Light lightBlock[MAX_LIGHTS]; };
layout(std140, binding = BINDING_NOISE) uniform NoiseBlock { NoiseTable noiseTable; };
layout(binding = BINDING_IMAGES) uniform sampler2D images[MAX_IMAGES];
layout(std430, binding = BINDING_ACCUMULATION) buffer AccumulationBlock { vec4 accumulation[]; };
layout(binding = BINDING_DISPLAY, r32ui) uniform writeonly uimage2D displayImage;
layout(std140, binding = BINDING_TREE) uniform TreeBlock { BvhNode treeBlock[MAX_UNIFORM_TREE_NODES]; };
layout(std430, binding = BINDING_TREE_STORAGE) readonly buffer TreeStorage { BvhNode treeStorage[]; };
layout(std430, binding = BINDING_SPHERE_STORAGE) readonly buffer SphereStorage { Sphere sphereStorage[]; };
layout(std430, binding = BINDING_STATUS) buffer StatusBlock { uint status[STATUS_WORDS]; };
layout(std430, binding = BINDING_TILE_RANGES) readonly buffer TileRanges { uint tileRanges[]; };
layout(std430, binding = BINDING_TILE_SPHERES) readonly buffer TileSpheres { uint tileSpheres[]; };
layout(std140, binding = BINDING_TILE_ORDER) uniform TileOrderBlock { uvec4 tileOrder[TILE_ORDER_CHUNK / 4u]; };
layout(std430, binding = BINDING_EDGE_LIST) buffer EdgeListBlock {
  uvec4 edgeHeader;
  uvec2 edgeEntries[];
};

#include "baked.glsl"

// The frame and, where the kernel is specialised to the scene's counts, its spheres, planes
// and lights, copied from the uniform blocks at the start of main, before any branch: lavapipe
// reads a uniform block with one scalar load only outside divergent control flow; after it,
// even at a constant offset, it gathers one load per lane (docs/performance.md, "Where the
// kernel's time goes").
Frame frame;
uint primaryTile;  // the pixel's tile (TILE_LISTS), set in main
uint shadowCell;   // the pixel's cell of shadow lists (SHADOW_LISTS), set in main
const uint SPHERE_CACHE = SPHERE_COUNT == COUNT_FROM_FRAME || SPHERE_COUNT == 0u ? 1u : SPHERE_COUNT;
const uint PLANE_CACHE = PLANE_COUNT == COUNT_FROM_FRAME || PLANE_COUNT == 0u ? 1u : PLANE_COUNT;
const uint LIGHT_CACHE = LIGHT_COUNT == COUNT_FROM_FRAME || LIGHT_COUNT == 0u ? 1u : LIGHT_COUNT;
Sphere sphereCache[SPHERE_CACHE];
Plane planeCache[PLANE_CACHE];
Light lightCache[LIGHT_CACHE];

void cacheScene() {
  frame = frameBlock;
  if (SPHERE_COUNT != COUNT_FROM_FRAME)
    for (uint i = 0u; i < SPHERE_CACHE; ++i) {
      if (BAKED) sphereCache[i] = bakedSphere(i);
      else sphereCache[i] = sphereBlock[i];
    }
  if (PLANE_COUNT != COUNT_FROM_FRAME)
    for (uint i = 0u; i < PLANE_CACHE; ++i) {
      if (BAKED) planeCache[i] = bakedPlane(i);
      else planeCache[i] = planeBlock[i];
    }
  if (LIGHT_COUNT != COUNT_FROM_FRAME)
    for (uint i = 0u; i < LIGHT_CACHE; ++i) {
      if (BAKED) lightCache[i] = bakedLight(i);
      else lightCache[i] = lightBlock[i];
    }
}

// Item i; i may differ between invocations (a hit's index): a cached item is then picked
// with selects, since lavapipe indexes a private array per lane through memory.
Sphere sphereAt(uint i) {
  if (SPHERE_TREE == SPHERE_TREE_STORAGE) return sphereStorage[i];
  if (SPHERE_COUNT == COUNT_FROM_FRAME) return sphereBlock[i];
  Sphere s = sphereCache[0];
  for (uint k = 1u; k < SPHERE_CACHE; ++k)
    if (i == k) s = sphereCache[k];
  return s;
}
Plane planeAt(uint i) {
  if (PLANE_COUNT == COUNT_FROM_FRAME) return planeBlock[i];
  Plane p = planeCache[0];
  for (uint k = 1u; k < PLANE_CACHE; ++k)
    if (i == k) p = planeCache[k];
  return p;
}
// (Not a ?: between the block and the cache: glslang stores the block's struct type, with its
// explicit layout, into the other, which is invalid SPIR-V.)
Light lightAt(uint i) {
  if (LIGHT_COUNT == COUNT_FROM_FRAME) return lightBlock[i];
  return lightCache[i];
}

// Material i (i differs between invocations): picked from the baked materials with selects.
Material materialAt(uint i) {
  if (!BAKED) return materials[i];
  Material m = bakedMaterial(0u);
  for (uint k = 1u; k < BAKED_MATERIAL_COUNT; ++k)
    if (i == k) m = bakedMaterial(k);
  return m;
}

// Loop bounds: constants where the kernel is specialised to the scene's counts.
uint sphereCount() { return SPHERE_COUNT == COUNT_FROM_FRAME ? frame.sphereCount : SPHERE_COUNT; }
uint planeCount() { return PLANE_COUNT == COUNT_FROM_FRAME ? frame.planeCount : PLANE_COUNT; }
uint lightCount() { return LIGHT_COUNT == COUNT_FROM_FRAME ? frame.lightCount : LIGHT_COUNT; }
// The sphere's latitude/longitude (two atans per hit) only for kinds that read it, the
// coordinate debug output and the uv pass. (No || here: glslang turns it into branches that are
// invalid SPIR-V outside a function.)
#ifdef RAYTEX_AOV
const bool SPHERE_LAT_LONG = ((SPHERE_TEXTURE_KINDS & TEX_2D_KINDS) | (PASS_MASK & (1u << AOV_UV))) != 0u;
#include "passes.glsl"
#else
const bool SPHERE_LAT_LONG = ((SPHERE_TEXTURE_KINDS & TEX_2D_KINDS) | uint(OUTPUT_MODE == OUTPUT_COORDS)) != 0u;
#endif

#include "noise.glsl"
#include "loop_budget.glsl"
#include "mapping.glsl"
#include "camera.glsl"
#include "intersect.glsl"
#ifdef RAYTEX_EDGE_PASS
#include "coverage.glsl"
#endif
#include "shading.glsl"
#ifdef RAYTEX_FILTER_BOX
#include "footprint.glsl"
#endif
#include "textures.glsl"

#ifdef RAYTEX_FILTER_BOX
// Most probes an anisotropic footprint is split into (closed-form kinds).
const uint MAX_PROBES = 8u;

// The texture colour at a hit, averaged over the footprint of the sample at `film` whose
// neighbours lie `spacing` pixels away. A grazing footprint is long and thin, and one box
// around its centre is a poor fit (perspective stretches its far end), so closed-form kinds
// split it into K probes along its long screen axis, each with its own exact position on
// the surface and 1/K of the length (anisotropic filtering).
vec3 albedoAt(Hit hit, Surface s, Material m, vec3 origin, vec2 film, float spacing) {
  vec3 dpdx, dpdy;
  Footprint fp;
  TexCoord tc = footprintAt(hit, s, origin, film, spacing, fp, dpdx, dpdy);
  if (IMAGE_FILTER == IMAGE_FILTER_STOCHASTIC) imageSeed = imageHash(floatBitsToUint(film.x) ^ imageHash(floatBitsToUint(film.y)));
#ifdef RAYTEX_EDGE_PASS
  shadeDpdx = dpdx;
  shadeDpdy = dpdy;
#endif
  if (EDGE_FLAGS) shadowRadius = 0.5 * (length(dpdx) + length(dpdy));
#ifdef RAYTEX_AOV
  keepFootprintPass(readsSolidCoord(m.textureKind) ? vec2(length(fp.dsdx), length(fp.dsdy))
                                                   : vec2(length(fp.duvdx), length(fp.duvdy)));
#endif
  float lx = length(dpdx), ly = length(dpdy);
  bool alongX = lx >= ly;
  float ratio = alongX ? lx / max(ly, 1.0e-30) : ly / max(lx, 1.0e-30);
  // Probes matter only where the long axis spans a good part of a check: no probe shorter
  // than a quarter of one (a footprint inside a check is already exact). Other kinds take one
  // probe, so textureColor has one call site: lavapipe runs every inlined copy of it (the
  // image lookups included) for each SIMD group, whatever kind its lanes hit.
  float checks = alongX ? filteredCells(m, fp.duvdx, fp.dsdx) : filteredCells(m, fp.duvdy, fp.dsdy);
  uint k = hasClosedFormFilter(m.textureKind) ? uint(clamp(ceil(min(ratio, 4.0 * checks)), 1.0, float(MAX_PROBES))) : 1u;
  if (k == 1u) return textureColor(m, tc, fp);
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
    vec3 dp = tangentPlaneOffset(origin, s.p, s.n, primaryRayUnnormalized(film + (alongX ? vec2(f, 0.0) : vec2(0.0, f))));
    sum += filteredBlend(m, texCoordNear(hit, s.p, dp), fp);
  }
  return mix(m.color1.rgb, m.color2.rgb, sum / float(k));
}
#else
// Point sampling: the texture at the hit (the course's method).
vec3 albedoAt(Hit hit, Surface s, Material m, vec3 origin, vec2 film, float spacing) {
  return textureColor(m, s.tc);
}
#endif

// Linear radiance of the sample at `film` (pixel units); `spacing` between samples.
vec3 radiance(vec3 origin, vec2 film, float spacing) {
  vec3 dir = primaryRay(film);
  startEdgeFlags(film, spacing);
  Hit hit = closestHit(origin, dir);
  endPrimaryEdges(origin, dir, hit);
  if (hit.kind == HIT_NONE) return frame.background.rgb;
  Surface s = surfaceAt(hit, origin, dir);
  Material m = materialAt(s.material);
#ifdef RAYTEX_EDGE_PASS
  shadeSelf = hit.kind == HIT_SPHERE ? hit.index : 0xFFFFFFFFu;
#endif
  vec3 albedo = albedoAt(hit, s, m, origin, film, spacing);
#ifdef RAYTEX_AOV
  keepSurfacePasses(mappedCoord(m, s.tc), s.n, hit.t, s.p, albedo);
  if (passesOnly) return vec3(0.0);
#endif
  return shade(s, m, albedo, -dir);
}

#ifdef RAYTEX_AOV
// The pass variant's samples: those this dispatch shades (N x N, or the progressive sample
// frame.sampleIndex), added to `sum` in the order and float operations of the other variants,
// then, where N > 1 and this dispatch writes the passes (not after progressive sample 0), the
// pixel centre once more, with the footprint of one pixel, for the passes alone. The last
// sample traced leaves its passes (passes.glsl): the centre's. One call of radiance, in a
// do-while (as RAYTEX_SUPERSAMPLE's). Returns the samples traced; `listed`: whether the coverage
// filter's edge pass shades the last shaded sample again (EDGE_FLAGS; its edges, not the
// centre's), and `object`, that sample's edge object.
uint traceWithPasses(vec3 origin, uvec2 pixel, inout vec3 sum, out bool listed, out uint object) {
  const uint n = SAMPLES_PER_SIDE;
  const uint shaded = PROGRESSIVE ? 1u : n * n;
  const uint traced = shaded + ((n > 1u && (!PROGRESSIVE || frame.sampleIndex == 0u)) ? 1u : 0u);
  uint i = 0u;
  listed = false;
  object = EDGE_NONE;
  do {
    uint k = PROGRESSIVE ? frame.sampleIndex : i;
    passesOnly = i == shaded;
    clearPasses();
    vec2 film = passesOnly ? vec2(pixel) + 0.5 : vec2(pixel) + (vec2(k % n, k / n) + 0.5) / float(n);
    vec3 r = radiance(origin, film, passesOnly ? 1.0 : 1.0 / float(n));
    if (!passesOnly) sum += r;
    if (EDGE_FLAGS && !passesOnly) {
      listed = edgeObject != EDGE_NONE || edgeShadow;
      object = edgeObject;
    }
  } while (++i < traced);
  return traced;
}
#endif

#ifdef RAYTEX_DEBUG_OUTPUT
// Debug outputs at the pixel centre: texture coordinates or texture colour, HIT_* in alpha.
vec4 debugOutput(vec3 origin, vec2 film) {
  vec3 dir = primaryRay(film);
  Hit hit = closestHit(origin, dir);
  if (hit.kind == HIT_NONE) return vec4(0.0);
  Surface s = surfaceAt(hit, origin, dir);
  Material m = materialAt(s.material);
  if (OUTPUT_MODE == OUTPUT_ALBEDO)
    return vec4(albedoAt(hit, s, m, origin, film, 1.0), float(hit.kind));
  return vec4(mappedCoord(m, s.tc), float(hit.kind));
}
#endif

// Appends the pixel (its index in the band) and its edge object to the coverage filter's list,
// growing the edge pass's indirect dispatch to cover it.
void listEdgePixel(uint outputIndex, uint object) {
  uint slot = atomicAdd(edgeHeader.w, 1u);
  edgeEntries[slot] = uvec2(outputIndex, object);
  atomicMax(edgeHeader.x, slot / EDGE_GROUP_SIZE + 1u);
}

// A linear colour as the window shows it: sRGB-encoded 8-bit channels packed in the
// swapchain's byte order, so that the viewer can copy the image into the swapchain as it is.
uint displayPixel(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  // The sRGB curve from square roots (Taylor's fit, within half a step of 8 bits above the
  // linear toe), cheaper than pow on lavapipe; the PNG path (encodeSrgb) is exact.
  vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
  vec3 curve = 0.662002687 * s1 + 0.684122060 * s2 - 0.323583601 * s3 - 0.0225411470 * c;
  vec3 srgb = mix(12.92 * c, curve, greaterThan(c, vec3(0.0031308)));
  return packUnorm4x8(frame.displayBgra != 0u ? vec4(srgb.bgr, 1.0) : vec4(srgb, 1.0));
}

// The invocation's pixel in the band: from its place in the dispatch, or, in a tile kernel,
// from the tile its workgroup reads (one load from a uniform block, the same for the whole
// group, before any branch). TILE_ORDER_NONE lands far below the image: nothing is stored.
uvec2 invocationPixel() {
  if (!TILE_ORDER) return gl_GlobalInvocationID.xy;
  const uint tile = tileOrder[gl_WorkGroupID.x / 4u][gl_WorkGroupID.x % 4u];
  return uvec2(tile & 0xFFFFu, tile >> 16u) * TILE_SIZE + gl_LocalInvocationID.xy;
}

#ifdef RAYTEX_EDGE_PASS
// The coverage filter's edge pass: invocation i of the indirect dispatch shades listed pixel i
// again (coverage.glsl): the centre's side of its edge and the far side, each at the middle of
// its part, mixed by their shares; a pixel listed for a shadow's edge alone, at its centre.
// Progressive (N x N samples, one per dispatch), it shades sample frame.sampleIndex's cell and
// adds it to the running sum, which the main kernel left as it was for listed pixels.
// Invocations past the list's end shade its last pixel and store nothing.
void main() {
  cacheScene();
  uint slot = gl_WorkGroupID.x * EDGE_GROUP_SIZE + gl_LocalInvocationIndex;
  uint count = edgeHeader.w;
  bool inside = slot < count;
  uvec2 entry = edgeEntries[min(slot, max(count, 1u) - 1u)];
  uint outputIndex = entry.x;
  uvec2 pixel = uvec2(outputIndex % frame.width, outputIndex / frame.width + frame.rowOffset);
  primaryTile = (pixel.y / TILE_SIZE) * frame.tileColumns + pixel.x / TILE_SIZE;
  shadowCell = (pixel.y / (TILE_SIZE * SHADOW_CELL)) * frame.shadowColumns + pixel.x / (TILE_SIZE * SHADOW_CELL);
  vec3 origin = frame.eye.xyz;
  const uint n = SAMPLES_PER_SIDE;
  uint k = PROGRESSIVE ? frame.sampleIndex : 0u;
  vec2 film = vec2(pixel) + (vec2(k % n, k / n) + 0.5) / float(n);
  float spacing = 1.0 / float(n);
  vec2 centreSide = film, farSide = film;
  float share = entry.y != EDGE_NONE ? edgeSplit(entry.y, origin, film, spacing, centreSide, farSide) : 1.0;
  // One call of radiance, in a do-while (as RAYTEX_SUPERSAMPLE's).
  vec3 sum = vec3(0.0);
  uint i = 0u;
  do {
    sum += (i == 0u ? share : 1.0 - share) * radiance(origin, i == 0u ? centreSide : farSide, spacing);
  } while (++i < (share < 1.0 ? 2u : 1u));
  checkLoopBudget(2u);
  if (!inside) return;
  if (!PROGRESSIVE) {
    outputPixels[outputIndex] = vec4(sum, 1.0);
    return;
  }
  sum += frame.sampleIndex == 0u ? vec3(0.0) : accumulation[outputIndex].rgb;
  accumulation[outputIndex] = vec4(sum, 1.0);
  imageStore(displayImage, ivec2(pixel), uvec4(displayPixel(sum * frame.sampleWeight)));
}
#else
void main() {
  cacheScene();
  // Invocations past the image's edge (in the last workgroups) trace the edge pixel and store
  // nothing: an early return would put all that follows in divergent control flow. Rows are
  // counted from the band's first (frame.rowOffset), and so is the output's row.
  uvec2 id = invocationPixel();
  bool inside = id.x < frame.width && id.y < frame.bandRows;
  uvec2 pixel = min(id + uvec2(0u, frame.rowOffset), uvec2(frame.width, frame.height) - 1u);
  uint outputIndex = (pixel.y - frame.rowOffset) * frame.width + pixel.x;
  primaryTile = (pixel.y / TILE_SIZE) * frame.tileColumns + pixel.x / TILE_SIZE;
  shadowCell = (pixel.y / (TILE_SIZE * SHADOW_CELL)) * frame.shadowColumns + pixel.x / (TILE_SIZE * SHADOW_CELL);
  vec3 origin = frame.eye.xyz;
#ifdef RAYTEX_DEBUG_OUTPUT
  vec4 result = debugOutput(origin, vec2(pixel) + 0.5);
#else
  // N x N stratified samples at the centres of the sub-pixel cells, box filtered. Progressive
  // rendering adds the same samples one per dispatch, in the same order and the same float
  // operations, so its last mean is bit-identical to the single-dispatch image. It writes the
  // running sum and the display pixel, not the float image: readbackFrame multiplies the sum
  // by the same weight on the host (one float multiply: the same bits).
  const uint n = SAMPLES_PER_SIDE;
  vec3 sum = vec3(0.0);
  if (PROGRESSIVE) sum = frame.sampleIndex == 0u ? vec3(0.0) : accumulation[outputIndex].rgb;
#if defined(RAYTEX_AOV)
  // The shaded samples and the passes (progressive: in the dispatch of sample 0).
  bool listed;
  uint object;
  checkLoopBudget(traceWithPasses(origin, pixel, sum, listed, object));
  if (inside && (!PROGRESSIVE || frame.sampleIndex == 0u)) writePasses(outputIndex);
  if (listed && inside) listEdgePixel(outputIndex, object);
  inside = inside && !(PROGRESSIVE && listed);
#elif defined(RAYTEX_SUPERSAMPLE)
  // N x N samples in one dispatch (N > 1, not progressive). No for loop: lavapipe tests a
  // loop's condition at the top of each pass and leaves only when no lane is left, so a for
  // loop runs its body once more with every lane masked off; a do-while tests at the bottom
  // (docs/performance.md, "Where the kernel's time goes").
  uint k = 0u;
  do {
    sum += radiance(origin, vec2(pixel) + (vec2(k % n, k / n) + 0.5) / float(n), 1.0 / float(n));
  } while (++k < n * n);
  checkLoopBudget(n * n);
#else
  // One sample per dispatch, with no loop around it: the pixel centre, or the progressive
  // sample frame.sampleIndex. (One call of radiance per build variant: the driver inlines each
  // call before the constants drop what a scene lacks, so a second call costs pipeline creation
  // its whole size again; a loop around this one costs more per pixel where it nests loops:
  // docs/performance.md, "One trace per kernel".)
  uint k = PROGRESSIVE ? frame.sampleIndex : 0u;
  sum += radiance(origin, vec2(pixel) + (vec2(k % n, k / n) + 0.5) / float(n), 1.0 / float(n));
  checkLoopBudget(1u);
  // A listed pixel is the edge pass's to write (its sample added to the running sum there).
  bool listed = EDGE_FLAGS && (edgeObject != EDGE_NONE || edgeShadow);
  if (listed && inside) listEdgePixel(outputIndex, edgeObject);
  inside = inside && !(PROGRESSIVE && listed);
#endif
  if (PROGRESSIVE) {
    if (inside) {
      accumulation[outputIndex] = vec4(sum, 1.0);
      imageStore(displayImage, ivec2(pixel), uvec4(displayPixel(sum * frame.sampleWeight)));
    }
    return;
  }
  vec4 result = vec4(sum * (1.0 / float(n * n)), 1.0);
#endif
  if (inside) outputPixels[outputIndex] = result;
}
#endif  // RAYTEX_EDGE_PASS
