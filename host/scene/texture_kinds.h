// The texture kinds as the host knows them: per row of shaders/kinds/kinds.h (its name, coordinate,
// noise table and cost) its host row (texture_kinds.cpp: its keys with their type, default, valid
// range and where each is packed for the GPU, and its solid period). The parser, its messages,
// --help, the GPU packing and docs/scene-format.md's table all read these rows. The kind's GLSL is
// shaders/kinds/<file>.glsl; its double-precision oracle is in host/reference/texture.cpp.
// Adding a kind: docs/adding-a-texture.md. No Vulkan, no oracle.
#pragma once

#include "common.h"
#include "scene.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

// How a key's value is written in a scene file.
enum class KeyType { Colour, Number, Whole, File, Word };

// Where packMaterial puts a key's value in gpu::Material (shaders/common.h).
// ImageFile and ImageWrap: packed with the scene's images (gpu_scene.cpp, packImageFields).
enum class MaterialSlot { Color1, Color2, ParamX, ParamY, ParamZ, ParamW, Octaves, ImageFile, ImageWrap };

// A number key's valid values: lo < (or <=) value < (or <=) hi; whole: an integer.
struct KeyRange {
  double lo = -1e300, hi = 1e300;
  bool loOpen = false, hiOpen = false;
  bool whole = false;
};

struct TextureKey {
  const char* name;
  KeyType type;
  MaterialSlot slot;
  KeyRange range;           // Number and Whole keys
  const char* meaning;      // for the docs' table
  // The TextureDesc field the key sets (the one matching its type).
  glm::vec3 TextureDesc::*colour = nullptr;
  float TextureDesc::*number = nullptr;
  int TextureDesc::*whole = nullptr;
  // A Word key: the words it takes, and how the i-th is stored and read back.
  std::vector<const char*> words;
  void (*setWord)(TextureDesc&, size_t) = nullptr;
  size_t (*word)(const TextureDesc&) = nullptr;
};

struct TextureKindInfo {
  TextureKind kind;            // its TEX_* value (common.h)
  const char* name;            // in scene files
  bool solid;                  // reads the 3D solid coordinate (else the 2D (u, v))
  bool needsNoise;             // reads the noise table (BINDING_NOISE)
  std::vector<TextureKey> keys;
  TextureDesc defaults;        // the values a texture starts from before its keys
  // The period of the pattern in solid coordinates, 0 if none (the host reduces the camera's
  // offset modulo it, in double, so the pattern stays exact far from the origin).
  double (*solidPeriod)(const TextureDesc&);
  // x86 instructions per pixel its code adds to a point-sampled kernel on lavapipe, for every
  // pixel the kernel renders, whatever the pixel shows (its COST in shaders/kinds/kinds.h;
  // tile_kernels.h weighs it: docs/performance.md, "Tile kernels").
  double kernelCost = 0;
};

// Every kind but TextureKind::None, in TEX_* order.
const std::vector<TextureKindInfo>& textureKinds();

// The row of a kind (TextureKind::None has none: throws std::invalid_argument).
const TextureKindInfo& textureKindInfo(TextureKind kind);

// The row named `name` in scene files, or nullptr.
const TextureKindInfo* findTextureKind(const std::string& name);

// A key of any kind named `name`, or nullptr.
const TextureKey* findTextureKey(const std::string& name);

// A key of `info` named `name`, or nullptr.
const TextureKey* findKindKey(const TextureKindInfo& info, const std::string& name);

// The row's defaults (TextureKind::None: an untextured TextureDesc).
TextureDesc defaultTexture(TextureKind kind);

// Whether the kind reads the 3D solid coordinate (false for None).
bool isSolidTexture(TextureKind kind);

// Whether the kind reads the 2D (u, v) of the shape's mapping (false for None).
bool readsUv(TextureKind kind);

// The scene-file name of a kind ("checker", "solid_checker", ...; "none").
const char* textureKindName(TextureKind kind);

// "image, checker, ... or dturbulence": the kinds, for messages and --help.
std::string textureKindList();

// What a number key accepts, as messages and the docs say it: "> 0", "a whole number from 1
// to 16", "any".
std::string describeRange(const KeyRange& range);

// "repeat or clamp": the words a Word key takes.
std::string describeWords(const TextureKey& key);

// Whether `value` is within `range`.
bool inRange(const KeyRange& range, double value);

// The docs' table of kinds and keys (docs/scene-format.md holds it verbatim; a test compares).
std::string textureKindsMarkdown();

// The material's texture words of gpu::Material, from the kind's row: each key's value in its
// slot (the image's element, size and wrap are packed with the scene's images: gpu_scene.cpp).
void packTexture(const TextureDesc& texture, gpu::Material* out);
