// Passes (AOVs, common.h's AOV_*): what the primary ray through the pixel centre sees, kept while
// it is traced and written to BINDING_AOV beside the image. Only in the RAYTEX_AOV modules;
// PASS_MASK (SPEC_PASS_MASK) says which passes they write: the stores of the others compile out.
// Every sample keeps its values (radiance, albedoAt, the box filters of images and noise), each
// cleared first; the kernel traces the pixel centre last (trace.comp.glsl, traceWithPasses), so
// what is kept at the end is the centre's.
//
// Needs (declared by the including kernel, after common.h): PASS_MASK, `frame`.
#ifndef RAYTEX_PASSES_GLSL
#define RAYTEX_PASSES_GLSL

layout(std430, binding = BINDING_AOV) writeonly buffer PassBlock { vec4 passPixels[]; };

struct PixelPasses {
  float covered;  // 1 on a surface, 0 on the background (where the values stay 0)
  vec3 coord;     // AOV_UV
  vec3 normal;    // AOV_NORMAL
  float depth;    // AOV_DEPTH
  vec3 position;  // AOV_POSITION, camera-relative
  vec3 albedo;    // AOV_ALBEDO
  vec2 footprint; // AOV_FOOTPRINT
  float lod;      // AOV_LOD
  float octaves;  // AOV_OCTAVES
};
PixelPasses pixelPasses;
bool passesOnly = false;  // the sample is the pixel centre traced for the passes alone: not shaded

void clearPasses() {
  pixelPasses = PixelPasses(0.0, vec3(0.0), vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), 0.0, 0.0);
}

// A hit's surface: its mapped coordinate, the normal facing the eye, its t along the unit
// primary direction, the point (camera-relative) and the texture colour.
void keepSurfacePasses(vec3 coord, vec3 normal, float depth, vec3 position, vec3 albedo) {
  pixelPasses.covered = 1.0;
  pixelPasses.coord = coord;
  pixelPasses.normal = normal;
  pixelPasses.depth = depth;
  pixelPasses.position = position;
  pixelPasses.albedo = albedo;
}

// The box filter's footprint widths, level and octaves (FILTER_BOX).
void keepFootprintPass(vec2 widths) { pixelPasses.footprint = widths; }
void keepLodPass(float lod) { pixelPasses.lod = lod; }
void keepOctavesPass(float octaves) { pixelPasses.octaves = octaves; }

// Whether pass `bit` (AOV_*) is written, and its plane: the requested passes below it.
bool passWanted(uint bit) { return ((PASS_MASK >> bit) & 1u) != 0u; }
uint passPlane(uint bit) { return uint(bitCount(PASS_MASK & ((1u << bit) - 1u))); }

// Stores the kept passes of the band's pixel `index`, each in its plane of width * bandRows.
void writePasses(uint index) {
  const uint planeSize = frame.width * frame.bandRows;
  const PixelPasses p = pixelPasses;
  const float w = p.covered;
  if (passWanted(AOV_UV)) passPixels[passPlane(AOV_UV) * planeSize + index] = vec4(p.coord, w);
  if (passWanted(AOV_NORMAL)) passPixels[passPlane(AOV_NORMAL) * planeSize + index] = vec4(p.normal, w);
  if (passWanted(AOV_DEPTH)) passPixels[passPlane(AOV_DEPTH) * planeSize + index] = vec4(p.depth, 0.0, 0.0, w);
  if (passWanted(AOV_POSITION)) passPixels[passPlane(AOV_POSITION) * planeSize + index] = vec4(p.position, w);
  if (passWanted(AOV_ALBEDO)) passPixels[passPlane(AOV_ALBEDO) * planeSize + index] = vec4(p.albedo, w);
  if (passWanted(AOV_FOOTPRINT))
    passPixels[passPlane(AOV_FOOTPRINT) * planeSize + index] = vec4(p.footprint, 0.0, w);
  if (passWanted(AOV_LOD)) passPixels[passPlane(AOV_LOD) * planeSize + index] = vec4(p.lod, 0.0, 0.0, w);
  if (passWanted(AOV_OCTAVES)) passPixels[passPlane(AOV_OCTAVES) * planeSize + index] = vec4(p.octaves, 0.0, 0.0, w);
}

#endif  // RAYTEX_PASSES_GLSL
