// The permutation table of Perlin noise: data that the GPU path (the BINDING_NOISE uniform
// buffer) and the double-precision oracle (noise.cpp) share. Not Perlin's published table: a
// Fisher-Yates shuffle of 0..255 driven by splitmix64 from a fixed seed, so it is the same on
// every platform and compiler.
#pragma once

#include "common.h"

#include <array>
#include <cstdint>

// The seed of the permutation shuffle.
constexpr uint64_t kNoiseSeed = 0x7261797465782d31ull;  // "raytex-1"

// The 256-entry permutation repeated twice (perm[i + 256] == perm[i]).
const std::array<uint32_t, 512>& noisePermutation();

// Packs noisePermutation() for the BINDING_NOISE uniform buffer, two neighbours a word:
// table->pairs[i >> 2][i & 3] = perm[i] | perm[(i + 1) % 512] << 16.
void fillNoiseTable(gpu::NoiseTable* table);
