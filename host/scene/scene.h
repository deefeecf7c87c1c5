// The scene model: what a .cfg file describes, independent of any backend.
// Parsed by parser.cpp, packed for the GPU by gpu_scene.cpp, evaluated on the
// CPU by the reference code in mapping.cpp / texture.cpp.
#pragma once

#include "error.h"
#include "kinds/kinds.h"

#include <glm/vec3.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

// A value per row of shaders/kinds/kinds.h, equal to its TEX_* id; the kind's host row is in
// texture_kinds.cpp.
#define RAYTEX_KIND_ENUM(ID, NAME, Kind, fn, file, COORD, FILTER, TABLE, COST) Kind = ID,
enum class TextureKind {
  None = TEX_NONE,
  RAYTEX_TEXTURE_KINDS(RAYTEX_KIND_ENUM)
  Count = TEX_KIND_COUNT,  // the number of values
};
#undef RAYTEX_KIND_ENUM

// How an image texture continues outside [0, 1]: tiled, or (clamp, a decal) its edge texels
// extended, as CLAMP_TO_EDGE.
enum class ImageWrap { Repeat, Clamp };

struct TextureDesc {
  TextureKind kind = TextureKind::None;
  glm::vec3 color1{1.0f};
  glm::vec3 color2{0.0f};
  float scale = 1.0f;     // frequency multiplier of the texture coordinate
  float strength = 1.0f;  // turbulence amount (marble, wood)
  float squares = 2.0f;   // checks per side of one texture tile (checker, solid_checker)
  int octaves = 1;        // noise octaves (turbulence-based kinds)
  int columns = 4;        // bricks per tile along u (bricks)
  float mortar = 0.1f;    // joint width as a fraction of a brick's height (bricks)
  std::string imagePath;  // image: resolved relative to the scene file that names it
  ImageWrap wrap = ImageWrap::Repeat;  // image
  FileLoc loc;            // where the texture was given, for image load errors
};

struct Material {
  std::string name;
  glm::vec3 ambient{0.1f};
  glm::vec3 diffuse{0.7f};
  glm::vec3 specular{0.3f};
  float shininess = 32.0f;
  TextureDesc texture;  // kind None: untextured Phong
  FileLoc loc;
};

// Where an object's texture lies on it (docs/scene-format.md, "Texture placement"): the
// mapping sees p' = R^-1 (p - o) + o and n' = R^-1 n (R = Rz Ry Rx of `rotate`, o the sphere's
// centre or the plane's origin d n), divides its coordinate by `scale` and adds `offset` last:
// (u, v) += (x, y) for 2D kinds, the solid coordinate += offset for solid kinds.
struct TexturePlacement {
  glm::dvec3 rotate{0.0};  // tex_rotate: degrees about the fixed x, y, z axes, x first
  double scale = 1.0;      // tex_scale: size of one texture repeat (> 0)
  glm::dvec3 offset{0.0};  // tex_offset
};

// Positions and sizes are double: a scene far from the origin keeps them exact until the
// host makes them camera-relative (gpu_scene.cpp). Colours are float.
struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 1.0;
  int material = -1;  // index into Scene::materials; -1: the default material
  TexturePlacement placement;
  FileLoc loc;
};

// x . normal = distance. normal is stored unit length.
struct Plane {
  glm::dvec3 normal{0.0, 1.0, 0.0};
  double distance = 0.0;
  int material = -1;
  TexturePlacement placement;  // scale: side of one repeated texture square
  FileLoc loc;
};

struct Light {
  glm::dvec3 position{0.0, 10.0, 0.0};
  glm::vec3 color{1.0f};
  FileLoc loc;
};

// Pinhole camera; fov is the vertical field of view in degrees.
struct Camera {
  glm::dvec3 eye{0.0, 0.0, 10.0};
  glm::dvec3 lookat{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fovY = 45.0;
};

// How a pixel's samples see textures and edges (docs/textures.md, docs/accuracy.md).
enum class TextureFilter {
  Point,     // the texture at the hit (the course's method)
  Box,       // textures averaged over the sample's footprint
  Coverage,  // Box, and the share of the pixel on each side of a silhouette, horizon or shadow edge
};
// The filter's name on the command line and in `render { filter = ...; }`, and back (nullopt: no such).
const char* textureFilterName(TextureFilter filter);
std::optional<TextureFilter> textureFilterNamed(const std::string& name);

// How the box and coverage filters filter image textures over the footprint (docs/textures.md,
// "Image filter methods"); the point filter looks an image up bilinearly at the hit.
enum class ImageFilter {
  Anisotropic,  // trilinear probes along the footprint's major axis (the default)
  Trilinear,    // one trilinear lookup at the level of the major axis
  Bilinear,     // one bilinear lookup at level 0, no mip levels
  Ewa,          // elliptical weighted average (Gaussian) over the texels of two levels, capped
  Stochastic,   // one texel per sample, drawn from the footprint's filter
};
// The method's name on the command line and in `render { image_filter = ...; }`, and back.
const char* imageFilterName(ImageFilter filter);
std::optional<ImageFilter> imageFilterNamed(const std::string& name);

// How to render, as a scene file may ask with `render { ... }`; command-line flags override.
struct RenderSettings {
  std::optional<int> width, height;
  std::optional<int> samplesPerPixel;  // a square number: an N x N stratified grid
  std::optional<TextureFilter> filter;
  std::optional<ImageFilter> imageFilter;
};

struct Scene {
  std::string path;                // the top-level scene file
  std::vector<std::string> files;  // every file read: path, then its #includes (for reloading)
  RenderSettings render;
  Camera camera;
  std::vector<Light> lights;
  glm::vec3 background{0.0f};
  glm::vec3 ambientLight{1.0f};
  std::vector<Material> materials;  // every material defined, in order of definition
  std::vector<Sphere> spheres;
  std::vector<Plane> planes;
};

// The material used by objects that name none.
Material defaultMaterial();

// An object's material: scene.materials[index], or `fallback` (defaultMaterial()) for -1.
const Material& materialAt(const Scene& scene, int index, const Material& fallback);

// Materials referenced by objects, in first-use order; -1 stands for the default material.
std::vector<int> usedMaterials(const Scene& scene);
