// Shared between GLSL (#include with GL_GOOGLE_include_directive) and C++.
// Every struct that crosses the host/GPU boundary is declared here once.
// Layout rules: std430 for storage buffers, std140 for uniform buffers; all
// structs are built from vec4/uvec4 and groups of four scalars so both rules
// and the C++ layout agree. The C++ side static_asserts every size.
#ifndef RAYTEX_COMMON_H
#define RAYTEX_COMMON_H

#include "kinds/kinds.h"

#ifdef __cplusplus
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
namespace gpu {
using uint = uint32_t;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#endif

// Compute workgroup: 8x8 (one tile); larger workgroups are no faster on lavapipe
// (docs/performance.md, "Where the kernel's time goes").
#define WORKGROUP_X 8
#define WORKGROUP_Y 8

// Descriptor bindings (set 0).
#define BINDING_OUTPUT 0     // storage vec4[width * height], row-major: linear radiance, a = 1
#define BINDING_FRAME 1      // uniform Frame
// The scene's objects, lights and materials are uniform buffers, not storage buffers: lavapipe
// turns each storage-buffer load inside control flow (a branch on what a ray hit, a loop) into
// a loop over the SIMD lanes with a bounds check per load, where a uniform-buffer load is one
// load, or a gather where the index differs per lane (docs/performance.md, "Where the kernel's
// time goes").
#define BINDING_SPHERES 2    // uniform Sphere[MAX_SPHERES]
#define BINDING_PLANES 3     // uniform Plane[MAX_PLANES]
#define BINDING_MATERIALS 4  // uniform Material[MAX_MATERIALS]
#define BINDING_LIGHTS 5     // uniform Light[MAX_LIGHTS]
#define BINDING_NOISE 6      // uniform NoiseTable (a uniform block: faster than a storage buffer on
                             // lavapipe, docs/performance.md, "Where the kernel's time goes")
#define BINDING_IMAGES 7     // sampler2D[MAX_IMAGES], one element per image file at its own size
                             // (1 x 1 placeholders past the scene's images)
#define BINDING_ACCUMULATION 8  // storage vec4[width * height]: running sums of progressive
                                // rendering (a 16-byte placeholder when not accumulating)
#define BINDING_DISPLAY 9  // r32ui storage image: progressive rendering's mean as 8-bit sRGB in the
                           // swapchain's byte order (Frame.displayBgra), which the viewer copies
                           // into the swapchain image (1 x 1 when not accumulating)
// The sphere tree (SPEC_SPHERE_TREE): its nodes in a uniform block where they fit, else the
// nodes and the spheres in storage buffers (placeholders where unused: the bindings exist).
#define BINDING_TREE 10            // uniform BvhNode[MAX_UNIFORM_TREE_NODES]
#define BINDING_TREE_STORAGE 11    // storage BvhNode[] (SPHERE_TREE_STORAGE)
#define BINDING_SPHERE_STORAGE 12  // storage Sphere[] (SPHERE_TREE_STORAGE)
#define BINDING_STATUS 13          // storage uint[STATUS_WORDS]: what the kernel reports to the host
// Per-tile sphere lists (SPEC_TILE_LISTS, host/accel/tile_lists.h): per tile its first entry and count,
// and the entries (indices of spheres); then, with SPEC_SHADOW_LISTS, per cell of tiles and light.
// 16-byte placeholders without them.
#define BINDING_TILE_RANGES 14   // storage uint[2 * tiles]
#define BINDING_TILE_SPHERES 15  // storage uint[]
// Tile kernels (SPEC_TILE_ORDER, host/gpu/tile_kernels.h): a frame dispatched as up to
// MAX_TILE_KERNELS kernels, each over its own tiles and specialised to the texture kinds those
// tiles can show. Workgroup x of a dispatch renders tile word x of the block bound at the
// dispatch's dynamic offset: its column | row << 16, or TILE_ORDER_NONE (nothing). A uniform
// block, not a storage buffer: lavapipe then treats the tile as the group's, not computed lane
// by lane (docs/performance.md, "Tile kernels"). Offset 0 holds TILE_ORDER_NONE.
#define BINDING_TILE_ORDER 16  // uniform, dynamic: uvec4[TILE_ORDER_CHUNK / 4], 4 words each
// The passes (SPEC_PASS_MASK, the AOV_* below): per requested pass, in bit order, a plane of
// width * bandRows vec4s (the band's rows, as BINDING_OUTPUT); a 16-byte placeholder without.
#define BINDING_AOV 17  // storage vec4[]
// The coverage filter (FILTER_COVERAGE): the main kernel lists the pixels an edge may cross
// (shaders/edge_flags.glsl), the edge pass shades those again (shaders/coverage.glsl). Storage:
// uvec4 (workgroups x, y, z of the edge pass, an indirect dispatch; the count), then per listed
// pixel uvec2 (its index in the band; the EDGE_ID of its edge's object, or EDGE_NONE for a
// shadow's edge alone); a 16-byte placeholder without the filter.
#define BINDING_EDGE_LIST 18
#define EDGE_GROUP_SIZE 64u   // edge pixels per workgroup of the edge pass (WORKGROUP_X * WORKGROUP_Y)
#define EDGE_KIND_SHIFT 30u   // EDGE_ID: HIT_* << EDGE_KIND_SHIFT | the object's index, or
#define EDGE_CREASE 3u        // EDGE_CREASE << EDGE_KIND_SHIFT | plane << EDGE_PLANE_SHIFT | plane
#define EDGE_PLANE_SHIFT 15u  // (the line where two planes meet)
#define EDGE_NONE 0xFFFFFFFFu
#define MAX_TILE_KERNELS 4u
#define TILE_ORDER_CHUNK 16384u  // tiles one dispatch renders at most: 64 KiB of words
#define TILE_ORDER_NONE 0xFFFFFFFFu

// What one render can hold: the uniform blocks' sizes, each within the 64 KiB of
// maxUniformBufferRange on lavapipe and NVIDIA (buildGpuScene reports a scene over them).
#define MAX_MATERIALS 256  // 256 * 112 bytes = 28 KiB
#define MAX_UNIFORM_SPHERES 1024  // 1024 * 64 bytes = 64 KiB
#define MAX_PLANES 256     // 256 * 144 bytes = 36 KiB (an EDGE_CREASE holds two indices)
#define MAX_LIGHTS 256     // 256 * 32 bytes = 8 KiB
// Image files per scene: one combined image sampler each, picked by a switch over constant
// indices (lavapipe indexes sampler arrays only with constants). 16 is Vulkan's guaranteed
// minimum of maxPerStageDescriptorSamplers and maxPerStageDescriptorSampledImages, so every
// device holds them.
#define MAX_IMAGES 16
// Spheres a scene may hold: over MAX_UNIFORM_SPHERES they are read from a storage buffer
// through the sphere tree (8 MiB at the limit).
#define MAX_SPHERES 131072

// The sphere tree: a bounding volume hierarchy over the spheres (host/accel/bvh.h, laid out by
// host/accel/gpu_tree.h), walked in the kernel instead of the loop over every sphere
// (shaders/sphere_tree.glsl).
#define SPHERE_TREE_NONE 0     // the loop over every sphere
#define SPHERE_TREE_UNIFORM 1  // nodes in BINDING_TREE, spheres in BINDING_SPHERES
#define SPHERE_TREE_STORAGE 2  // nodes in BINDING_TREE_STORAGE, spheres in BINDING_SPHERE_STORAGE
#define MAX_UNIFORM_TREE_NODES 2048  // 2048 * 32 bytes = 64 KiB: a tree over 1024 spheres
#define TREE_LEAF_SIZE 1u            // spheres in a leaf, at most
#define TREE_LEAF_SHIFT 24u          // BvhNode.spheres: count << TREE_LEAF_SHIFT | first
// Primary rays of a scene with a tree test the spheres listed for their tile of
// TILE_SIZE x TILE_SIZE pixels (one workgroup), nearest first: a ray stops at the first sphere
// whose nearest point lies beyond its hit. A tile with more than TILE_LIST_MAX walks the tree
// (its count is TILE_USE_TREE). The host builds lists of at most TILE_FILL_LIMIT entries a
// tile on average; over that every tile walks the tree.
#define TILE_SIZE 8u
#define TILE_LIST_MAX 128u
#define TILE_USE_TREE 0xFFFFFFFFu
#define TILE_FILL_LIMIT 64u
// Shadow rays of such a scene test the spheres listed for their cell of SHADOW_CELL x
// SHADOW_CELL tiles (fewer lists to build on each camera move than one a tile) and light
// (SPEC_SHADOW_LISTS, host/accel/shadow_lists.h), in the same buffers after the primary lists, where
// the scene has at most SHADOW_LIST_MAX_LIGHTS lights and SHADOW_LIST_MAX_PLANES planes (the
// host projects every sphere's shadow onto every plane for every light).
#define SHADOW_LIST_MAX_LIGHTS 4u
#define SHADOW_LIST_MAX_PLANES 8u
#define SHADOW_CELL 2u
#define SHADOW_LIST_MAX 32u  // spheres in a cell's list for a light; over that its rays walk the tree
// Where a cell's list is long, a shadow ray of a scene over MAX_UNIFORM_SPHERES from a point
// between a plane and the light looks up the light's shadow grid (host/accel/shadow_grid.h,
// Frame.shadowGrids): a grid over the plane listing, per grid cell, the spheres whose shadow
// covers it, two words a cell (first entry, count), row by row, in BINDING_TILE_RANGES.
// Scenes with more spheres than the loop is specialised to (MAX_SPECIALISED_COUNT) walk the tree
// (docs/performance.md, "The sphere tree"); fewer keep the loop, unrolled.
#define SPHERE_TREE_MIN_SPHERES 9

// Lavapipe ends a kernel's loops after 65 535 passes per SIMD group, counted over every loop of
// the kernel, and silently drops the rest of its work. Kernels built with SPEC_LOOP_BUDGET > 0
// count their loops' passes per group and, before the driver's limit, stop and set
// STATUS_LOOP_BUDGET in BINDING_STATUS; the host reports it.
#define STATUS_LOOP_BUDGET 1u  // bit of word 0: some group's loops passed the budget
// Octave counts above this are clamped (on the host: kNoiseMaxOctaves, host/reference/noise.h).
#define NOISE_MAX_OCTAVES 16u
// Loop passes per sample bounded by constants, reserved for in the budget: the noise kinds' octave
// loops (each runs in every SIMD group with its kind, at most NOISE_MAX_OCTAVES passes, and one
// masked), the box filter's probes (9) and the image filter's: at most 32 probes on a sphere, or
// EWA_MAX_TEXELS at each of two levels, and one masked.
#define LOOP_PASSES_PER_SAMPLE (4u * (NOISE_MAX_OCTAVES + 1u) + 9u + 33u)
#define STATUS_WORDS 4

// Texture kinds (Material.textureKind): TEX_NONE, TEX_<NAME> per row of kinds/kinds.h, and
// TEX_2D_KINDS. Bit (1 << kind) of SPEC_SPHERE_TEXTURE_KINDS and SPEC_PLANE_TEXTURE_KINDS says
// the kind is on a sphere or a plane; absent kinds compile to nothing.

// Specialisation constant ids.
#define SPEC_SPHERE_TEXTURE_KINDS 0  // uint bit mask of the TEX_* kinds on spheres
#define SPEC_OUTPUT_MODE 1    // OUTPUT_*
#define SPEC_SAMPLES_PER_SIDE 2  // N: N x N stratified samples per pixel (shaded output)
#define SPEC_PROGRESSIVE 3  // 1: each dispatch adds sample Frame.sampleIndex of the N x N to
                           // BINDING_ACCUMULATION and writes the mean so far (the viewer)
#define SPEC_PLANE_TEXTURE_KINDS 4  // uint bit mask of the TEX_* kinds on planes
#define SPEC_SPHERE_COUNT 5  // the scene's counts, or COUNT_FROM_FRAME: read Frame's at run time
#define SPEC_PLANE_COUNT 6
#define SPEC_LIGHT_COUNT 7
#define SPEC_TEXTURE_PLACEMENT 10  // false: no object's placement needs the kernel (mapping.glsl)
#define SPEC_IMAGE_COUNT 11  // image files the scene's objects use (switch cases past it compile out)
#define SPEC_SPHERE_TREE 12  // SPHERE_TREE_*
#define SPEC_LOOP_BUDGET 13  // loop passes a SIMD group may make (0: not counted)
#define SPEC_TILE_LISTS 14   // 1: primary rays test their tile's spheres (BINDING_TILE_*)
#define SPEC_TILE_ORDER 15   // 1: workgroups render the tiles of BINDING_TILE_ORDER (tile kernels)
#define SPEC_SHADOW_LISTS 16 // 1: shadow rays test their cell's and light's spheres (BINDING_TILE_*)
#define SPEC_PASS_MASK 17    // bit (1 << AOV_*) per pass written to BINDING_AOV (the RAYTEX_AOV modules)
#define SPEC_TEXTURE_FILTER 18  // FILTER_*: FILTER_COVERAGE makes the box kernel list edge pixels
#define SPEC_IMAGE_FILTER 19    // IMAGE_FILTER_*: how the box kernel filters image textures

// Scenes with at most this many spheres, planes or lights get kernels with the count
// built in (the loops over them unrolled); larger ones loop to Frame's count. On lavapipe a
// loop bounded by a uniform is markedly slower than the unrolled one (docs/performance.md,
// "Specialised against unspecialised pipelines").
#define MAX_SPECIALISED_COUNT 8
#define COUNT_FROM_FRAME 0xFFFFFFFFu

// Scenes with at most these many of each get kernels with the values of their spheres, planes,
// lights and materials built in (SPEC_BAKED, shaders/baked.glsl): headless renders, whose camera
// (and so the camera-relative positions) is fixed. Item k of a kind is laid out as its uniform
// block's struct from word BAKED_<KIND>_WORD + k * BAKED_<KIND>_STRIDE; strides are whole tens,
// so that shaders/baked.glsl names an item's words by their tens.
#define BAKED_SPHERE_STRIDE 20u       // words per item (sizeof(Sphere) / 4 = 16, padded)
#define BAKED_PLANE_STRIDE 40u        // 36
#define BAKED_LIGHT_STRIDE 10u        // 8
#define BAKED_MATERIAL_STRIDE 30u     // 28
#define SPEC_BAKED 8                  // 1: the kernel reads the BAKED_* words, not the uniform blocks
#define SPEC_BAKED_MATERIAL_COUNT 9   // the scene's materials (at most MAX_BAKED_MATERIALS)
#define SPEC_BAKED_WORDS 1000         // constant_id of word 0
#define MAX_BAKED_SPHERES 4u
#define MAX_BAKED_PLANES 4u
#define MAX_BAKED_LIGHTS 4u
#define MAX_BAKED_MATERIALS 8u   // one per object: any scene within the object limits
#define BAKED_SPHERE_WORD 0u          // words 0-79: 4 spheres
#define BAKED_PLANE_WORD 80u          // 80-239: 4 planes
#define BAKED_LIGHT_WORD 240u         // 240-279: 4 lights
#define BAKED_MATERIAL_WORD 280u      // 280-519: 8 materials
#define BAKED_WORD_COUNT 520

// The largest texture coordinate the kernel forms (mapping.glsl, clampTexCoord) or the host
// packs: far beyond float resolution (past 2^24 no fraction is left), and small enough that
// squares, sums of three and 2^15 times it (turbulence's 16th octave) stay finite. Clamping to
// it keeps every coordinate finite for any accepted tex_scale, scale, squares or strength (a
// pattern that fine is far below a pixel); ordinary coordinates lie far inside it, unchanged.
#define TEXCOORD_LIMIT 1.0e18

// The largest radiance a sample returns (shading.glsl, shade; the reference clamps alike): a
// product of large colours would overflow to infinity (and NaN where it meets a zero). Far
// above white, and the sum of 64 x 64 samples of it stays finite.
#define RADIANCE_LIMIT 1.0e30

// Texture filtering: a build variant of the kernel (RAYTEX_FILTER_BOX), not a constant.
#define FILTER_POINT 0  // point-sample textures at the hit (the course's method)
#define FILTER_BOX 1    // average over the sample's footprint (ray differentials): in closed
                        // form for checker, solid_checker and bricks, band-limited for the
                        // noise kinds, from the mip chain for images (docs/textures.md)
#define FILTER_COVERAGE 2  // FILTER_BOX, and where a silhouette, the horizon or a shadow's edge
                           // crosses the pixel, the share of the pixel on each side in closed
                           // form (shaders/coverage.glsl, docs/accuracy.md)

// How FILTER_BOX (and FILTER_COVERAGE) filters image textures over the footprint
// (shaders/kinds/image.glsl, image_filters.glsl; docs/textures.md, "Image filter methods").
#define IMAGE_FILTER_ANISOTROPIC 0  // trilinear probes along the footprint's major axis (default)
#define IMAGE_FILTER_TRILINEAR 1    // one trilinear lookup at the level of the major axis
#define IMAGE_FILTER_BILINEAR 2     // one bilinear lookup at level 0: no mip levels
#define IMAGE_FILTER_EWA 3          // elliptical Gaussian over the texels of two levels (capped)
#define IMAGE_FILTER_STOCHASTIC 4   // one texel per sample, drawn from the footprint's filter
// Most texels the EWA filter weighs at each of its two levels: a footprint whose ellipse spans
// more at the level of its minor axis is filtered at a coarser level. Two levels of it fit the
// loop passes reserved for the anisotropic filter's 32 probes (LOOP_PASSES_PER_SAMPLE).
#define EWA_MAX_TEXELS 16u

// Material.imageIndex's wrap bit: the image appears once (CLAMP_TO_EDGE), not tiled.
#define IMAGE_WRAP_CLAMP 0x10000u

// What the kernel writes per pixel.
#define OUTPUT_SHADED 0  // rgb = linear radiance, a = 1
#define OUTPUT_COORDS 1  // rgb = texture coordinate (u, v, w; w = 0 for 2D), a = HIT_*
#define OUTPUT_ALBEDO 2  // rgb = texture colour (the diffuse coefficient), a = HIT_*

// Passes (AOVs, host/scene/passes.h): bit AOV_<NAME> of a kernel's pass mask. Each requested pass is
// a plane of vec4 per pixel in BINDING_AOV, in bit order: its values in xyz (unused ones 0) and
// the pixel's coverage in w (1 on a surface, 0 on the background, where xyz are 0 too).
// They come from the primary ray through the pixel centre, with the footprint of one pixel:
// with N x N samples the pass kernel traces the centre once more (shaders/passes.glsl).
// "2D kinds" below are TEX_2D_KINDS and untextured materials; the rest are solid kinds.
#define AOV_UV 0         // the mapped coordinate: (u, v, 0), or the solid coordinate for solid kinds
#define AOV_NORMAL 1     // the unit normal facing the viewer (flipped on a back side), world axes
#define AOV_DEPTH 2      // x: the ray's t from the eye (the primary ray's direction is unit length)
#define AOV_POSITION 3   // the hit, camera-relative (the host adds the eye in double)
#define AOV_ALBEDO 4     // the texture colour (the diffuse coefficient), with the kernel's filter
// xy: the box filter's footprint along screen x and y, in texture units (one tile or one unit
// of the solid coordinate is 1): the lengths of d(u, v)/dx and d(u, v)/dy for 2D kinds, of the
// solid coordinate's d/dx and d/dy for solid kinds, for a step of one pixel (ray differentials
// on the tangent plane, shaders/footprint.glsl). FILTER_BOX; 0 with FILTER_POINT.
#define AOV_FOOTPRINT 5
#define AOV_LOD 6      // x: the mip level the box filter reads an image at (0: the image itself); 0 for other kinds
#define AOV_OCTAVES 7  // x: the noise octaves the box filter evaluates (the finer ones add their mean); 0 without noise
#define AOV_COUNT 8

// Alpha of the debug outputs: what the primary ray hit.
#define HIT_NONE 0
#define HIT_PLANE 1
#define HIT_SPHERE 2

// Permutation table of improved Perlin noise: 256 entries repeated to 512,
// four per uvec4 (std140 pads scalar arrays to 16 bytes, so pack them).
#define NOISE_PERM_SIZE 512

// A light's shadow grid over a plane, along the plane's tangent and binormal (Plane).
struct ShadowGrid {
  uint plane;       // the plane it lies on
  uint columns;     // cells a row
  uint rows;        // TILE_USE_TREE: the light has no grid
  uint firstRange;  // the word of its first cell's range in BINDING_TILE_RANGES
  vec4 corner;      // x, y: the grid's corner along the tangent and binormal; z: 1 / cell size
};

// Every position on the GPU is relative to the camera (computed on the host in double),
// so hit points near the camera stay exact however far the scene is from the origin.
struct Frame {
  vec4 eye;            // xyz: camera position: (0, 0, 0), positions being camera-relative
  vec4 cameraRight;    // xyz: right axis * tan(fovY/2) * aspect
  vec4 cameraUp;       // xyz: up axis * tan(fovY/2)
  vec4 cameraForward;  // xyz: unit view direction
  vec4 background;     // rgb: colour of rays that hit nothing
  vec4 ambientLight;   // rgb
  uint width;
  uint height;
  uint sphereCount;
  uint planeCount;
  uint lightCount;
  uint sampleIndex;    // progressive: which of the N x N samples this dispatch adds (row-major)
  float sampleWeight;  // progressive: 1 / (sampleIndex + 1), the mean's weight (host-computed)
  uint displayBgra;    // progressive: 1 packs BINDING_DISPLAY as B, G, R, A bytes, 0 as R, G, B, A
  // The band of rows this dispatch renders, BINDING_OUTPUT holding its bandRows rows: an image
  // whose vec4s pass maxStorageBufferRange is rendered band after band (renderer.h, selectBand).
  uint rowOffset;
  uint bandRows;
  uint treeNodeCount;  // nodes of the sphere tree (SPEC_SPHERE_TREE)
  uint tileColumns;    // tiles per row of the image (SPEC_TILE_LISTS)
  uint shadowRanges;   // first word of the shadow lists' ranges in BINDING_TILE_RANGES (SPEC_SHADOW_LISTS)
  uint shadowColumns;  // shadow cells per row of the image
  uint pad1;
  uint pad2;
  ShadowGrid shadowGrids[SHADOW_LIST_MAX_LIGHTS];  // per light
};

// Texture placement (docs/textures.md, "Texture placement") is packed by the host in double:
// texRotation is the unit quaternion (xyz, w) of R^-1, the inverse of tex_rotate ((0, 0, 0, 1)
// without one), which the mapping applies to the normal (sphere) or the camera-relative
// position (plane's solid coordinate).
struct Sphere {
  vec4 centerRadius;  // xyz: centre relative to the camera, w: radius
  vec4 texRotation;   // quaternion of R^-1
  vec4 solidOffset;   // xyz: tex_offset of a solid kind (0 for 2D kinds), w: tex_scale s
  uint material;
  float uOffset;      // tex_offset.xy of a 2D kind, added to (u, v)
  float vOffset;
  uint clampV;        // 1: image rows clamp at the poles (s = 1 and no v offset), 0: v repeats
};

// Plane x.n = d with its texture frame, computed on the host in double: tangent and
// binormal are unit, orthogonal to the normal and each other (the placed frame R t', R b').
// With x the camera-relative position, the texture coordinates are u_p/s = x.t/s + uvOffset.x
// (the notes' o' = d n drops out: n.t = 0), solid = R^-1 x / s + solidOffset and the image
// lookup (column, row) = x.(imageRight, imageDown)/s + their w, the offsets holding the
// camera's position and tex_offset reduced modulo the texture's period (host, in double).
struct Plane {
  vec4 normalDistance;  // xyz: unit normal n, w: distance from the camera, d - n.eye
  vec4 tangentScale;    // xyz: tangent t, w: tex_scale s
  vec4 binormal;        // xyz: binormal b
  vec4 uvOffset;        // xy: fractional part of (eye.t, eye.b)/s + tex_offset; zw: integer part mod 4096
  vec4 solidOffset;     // xyz: (R^-1 (eye - o) + o)/s + tex_offset modulo the solid texture's period
  vec4 texRotation;     // quaternion of R^-1 (the solid coordinate)
  vec4 imageRight;      // xyz: the image's rows run along it (unit, in the plane), w: offset mod 1
  vec4 imageDown;       // xyz: from the image's top row to its bottom (unit, in the plane), w: offset
  uint material;
  uint pad0;
  uint pad1;
  uint pad2;
};

struct Material {
  vec4 ambient;    // rgb: k_a
  vec4 diffuse;    // rgb: k_d (replaced by the texture colour when textured)
  vec4 specular;   // rgb: k_s, w: shininess
  vec4 color1;     // rgb: first texture colour
  vec4 color2;     // rgb: second texture colour
  vec4 params;     // x: scale (frequency), y: strength (turbulence amount), z: squares, w: unused
  uint textureKind;  // TEX_*
  uint octaves;
  // TEX_IMAGE: bits 0-7 the element of BINDING_IMAGES, bits 8-15 its mip levels, bit 16
  // (IMAGE_WRAP_CLAMP) wrap = clamp; imageSize: width | height << 16 (sides <= 16384).
  uint imageIndex;
  uint imageSize;
};

struct Light {
  vec4 position;  // xyz: relative to the camera
  vec4 color;     // rgb
};

// A node of the sphere tree, depth first from the root at 0. The box holds every sphere below,
// camera-relative and rounded outward. A walk enters the box or goes on at `next`, the node
// after this one's subtree (no stack); an inner node's first child is the next node, ordered
// nearer the camera first. spheres: a leaf's count << TREE_LEAF_SHIFT | its first sphere (its
// spheres are consecutive), 0 for an inner node.
struct BvhNode {
  vec3 lo;
  uint next;
  vec3 hi;
  uint spheres;
};

// Entry i holds perm[i] | perm[i + 1] << 16 (perm: the 256-entry permutation repeated, so
// perm[512] = perm[0]): one load gives both corners along an axis, and Perlin's 14 table
// lookups per noise value become 7. Lavapipe gathers them one lane at a time.
struct NoiseTable {
  uvec4 pairs[NOISE_PERM_SIZE / 4];
};

#ifdef __cplusplus
static_assert(sizeof(ShadowGrid) == 32, "ShadowGrid layout");
static_assert(sizeof(Frame) == 160 + 32 * SHADOW_LIST_MAX_LIGHTS, "Frame layout");
static_assert(sizeof(Sphere) == 64, "Sphere layout");
static_assert(sizeof(Plane) == 144, "Plane layout");
static_assert(sizeof(Material) == 112, "Material layout");
static_assert(sizeof(Light) == 32, "Light layout");
static_assert(sizeof(BvhNode) == 32, "BvhNode layout");
static_assert(MAX_UNIFORM_TREE_NODES >= 2 * MAX_UNIFORM_SPHERES - 1, "a tree over the uniform spheres fits its block");
static_assert(MAX_SPHERES < (1u << TREE_LEAF_SHIFT), "BvhNode.spheres holds a first sphere");
static_assert(MAX_SPHERES < (1u << EDGE_KIND_SHIFT) && 2 * EDGE_PLANE_SHIFT <= EDGE_KIND_SHIFT &&
                  MAX_PLANES <= (1u << EDGE_PLANE_SHIFT) && HIT_SPHERE != EDGE_CREASE && HIT_PLANE != EDGE_CREASE,
              "an EDGE_ID holds a sphere, a plane or two planes");
static_assert(TILE_SIZE == WORKGROUP_X && TILE_SIZE == WORKGROUP_Y, "a tile is a workgroup");
static_assert(sizeof(NoiseTable) == NOISE_PERM_SIZE * 4, "NoiseTable layout");
static_assert(sizeof(Sphere) / 4 <= BAKED_SPHERE_STRIDE && sizeof(Plane) / 4 <= BAKED_PLANE_STRIDE &&
                  sizeof(Light) / 4 <= BAKED_LIGHT_STRIDE && sizeof(Material) / 4 <= BAKED_MATERIAL_STRIDE &&
                  BAKED_PLANE_WORD == BAKED_SPHERE_WORD + MAX_BAKED_SPHERES * BAKED_SPHERE_STRIDE &&
                  BAKED_LIGHT_WORD == BAKED_PLANE_WORD + MAX_BAKED_PLANES * BAKED_PLANE_STRIDE &&
                  BAKED_MATERIAL_WORD == BAKED_LIGHT_WORD + MAX_BAKED_LIGHTS * BAKED_LIGHT_STRIDE &&
                  BAKED_WORD_COUNT == BAKED_MATERIAL_WORD + MAX_BAKED_MATERIALS * BAKED_MATERIAL_STRIDE,
              "baked scene layout (shaders/baked.glsl names the words by these tens)");
}  // namespace gpu
#endif

#endif  // RAYTEX_COMMON_H
