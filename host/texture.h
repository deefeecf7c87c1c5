// Texture kinds: names, defaults, and which mapping each one uses.
// (The CPU double-precision evaluation used as a test oracle lives here too.)
#pragma once

#include "mapping.h"
#include "scene.h"

#include <glm/vec3.hpp>

#include <string>

// The scene-file name of a kind ("checker", "solid_checker", ...).
const char* textureKindName(TextureKind kind);

// Looks up a scene-file name; false if it names no kind.
bool textureKindFromName(const std::string& name, TextureKind* kind);

// Solid (3D) kinds take (u, v, w): (n+1)/2 on a sphere, p/tex_scale on a plane.
// The others (image, checker) take the 2D (u, v) of the shape's mapping.
bool isSolidTexture(TextureKind kind);

// The parameters a kind starts from before the scene file overrides them.
TextureDesc defaultTexture(TextureKind kind);

// --- CPU double-precision evaluation: the oracle of shaders/textures.glsl ---
// The same formulas as the GPU (docs/textures.md), with q = solid * scale and
// colour = mix(color1, color2, t), t clamped to [0,1]:
//   checker        t = parity of floor(u*sq) + floor(v*sq) + sq*(tile.x + tile.y),
//                  sq = max(round(squares), 1) (whole checks per tile): even 0, odd 1
//   solid_checker  t = parity of floor(sx*sq) + floor(sy*sq) + floor(sz*sq), sq = squares
//   noise          t = 0.5 + 0.5 * perlinNoise(q)
//   marble         s = 0.5 + 0.5 * sin(pi * (q.x + q.y) + strength * turbulence(q, octaves)), t = s^3
//   wood           r = |solid.xz - (0.5, 0.5)|  (distance from the y axis through the cube centre)
//                  g = scale * r + strength * turbulence((q.x, q.y / 4, q.z), octaves),
//                  t = fract(g)^2
//   turbulence     t = strength * turbulence(q, octaves)
//   dturbulence    t = strength * dturbulence(q, octaves)

// The blend factor t in [0,1] between color1 (0) and color2 (1) of a procedural kind
// (the checkers give exactly 0 or 1). Throws std::invalid_argument for None and Image.
double textureBlendReference(const TextureDesc& texture, const TexCoordD& tc);

// mix(color1, color2, textureBlendReference(texture, tc)) for every procedural kind.
// Image textures need the decoded image and TextureKind::None the material's diffuse
// colour, neither of which is here: both throw std::invalid_argument.
glm::dvec3 textureColorReference(const TextureDesc& texture, const TexCoordD& tc);
