// The specialisation constants' table (kernel_key.h): every word of KernelKey but edgePass is one
// constant's, each id is one constant's, and keys compare by all their words.
#include "kernel_key.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <set>
#include <vector>

TEST(SpecConstants, EveryWordOfTheKeyButTheEdgePassIsOneConstants) {
  std::vector<int> owners(sizeof(KernelKey) / 4, 0);
  std::set<uint32_t> ids;
  for (const SpecConstant& c : specConstants()) {
    ASSERT_EQ(c.offset % 4, 0u);
    ASSERT_LE(c.offset / 4 + c.words, owners.size());
    for (uint32_t i = 0; i < c.words; ++i) {
      ++owners[c.offset / 4 + i];
      EXPECT_TRUE(ids.insert(c.id + i).second) << "id " << c.id + i << " twice";
    }
  }
  for (size_t w = 0; w < owners.size(); ++w) {
    const bool edgePass = w == offsetof(KernelKey, edgePass) / 4;
    EXPECT_EQ(owners[w], edgePass ? 0 : 1) << "word " << w << " of KernelKey";
  }
}

TEST(SpecConstants, KeysDifferingInAnyWordDiffer) {
  const KernelKey base;
  for (size_t w = 0; w < sizeof(KernelKey) / 4; ++w) {
    KernelKey other = base;
    unsigned char* bytes = reinterpret_cast<unsigned char*>(&other);
    uint32_t word = 0;
    std::memcpy(&word, bytes + 4 * w, 4);
    word ^= 1u;
    std::memcpy(bytes + 4 * w, &word, 4);
    EXPECT_FALSE(other == base) << "word " << w;
  }
  EXPECT_TRUE(KernelKey(base) == base);
}
