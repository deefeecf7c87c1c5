// The texture kinds evaluated on the CPU in double precision: the tests' oracle of
// shaders/kinds/*.glsl, written from docs/textures.md independently of the GPU path (which
// never includes this file). The kinds' names, keys and defaults are in texture_kinds.h.
#pragma once

#include "mapping.h"
#include "scene.h"

#include <glm/vec3.hpp>


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
//   bricks         U = (tile.x + u) C, V = (tile.y + v) 2C (C = columns), row = floor(V),
//                  x = U - (row odd ? 1/2 : 0); t = 1 (mortar) where fract(V) is within
//                  mortar/2 of a whole number or fract(x) within mortar/4, else 0

// The blend factor t in [0,1] between color1 (0) and color2 (1) of a procedural kind
// (the checkers give exactly 0 or 1). Throws std::invalid_argument for None and Image.
double textureBlendReference(const TextureDesc& texture, const TexCoordD& tc);

// mix(color1, color2, textureBlendReference(texture, tc)) for every procedural kind.
// Image textures need the decoded image and TextureKind::None the material's diffuse
// colour, neither of which is here: both throw std::invalid_argument.
glm::dvec3 textureColorReference(const TextureDesc& texture, const TexCoordD& tc);
