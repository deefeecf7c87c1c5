#include "noise_permutation.h"

#include <utility>

namespace {

// splitmix64 (Steele, Lea, Flood 2014): a tiny 64-bit generator whose output
// depends only on unsigned 64-bit arithmetic, hence identical everywhere.
uint64_t splitmix64Next(uint64_t* state) {
  uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Uniform integer in [0, n) without modulo bias (rejects the top partial block).
uint32_t uniformBelow(uint64_t* state, uint32_t n) {
  const uint64_t limit = UINT64_MAX - UINT64_MAX % n;
  uint64_t r;
  do {
    r = splitmix64Next(state);
  } while (r >= limit);
  return static_cast<uint32_t>(r % n);
}

std::array<uint32_t, 512> makePermutation() {
  std::array<uint32_t, 512> perm{};
  for (uint32_t i = 0; i < 256; ++i) perm[i] = i;
  uint64_t state = kNoiseSeed;
  for (uint32_t i = 255; i > 0; --i) {  // Fisher-Yates, from the top down
    uint32_t j = uniformBelow(&state, i + 1);
    std::swap(perm[i], perm[j]);
  }
  for (uint32_t i = 0; i < 256; ++i) perm[i + 256] = perm[i];
  return perm;
}

}  // namespace

const std::array<uint32_t, 512>& noisePermutation() {
  static const std::array<uint32_t, 512> perm = makePermutation();
  return perm;
}

void fillNoiseTable(gpu::NoiseTable* table) {
  const std::array<uint32_t, 512>& perm = noisePermutation();
  for (int i = 0; i < NOISE_PERM_SIZE; ++i)
    table->pairs[i >> 2][i & 3] = perm[i] | perm[(i + 1) % NOISE_PERM_SIZE] << 16;
}
