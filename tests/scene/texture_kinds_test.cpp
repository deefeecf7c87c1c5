// The texture-kind table (host/scene/texture_kinds.h over shaders/kinds/kinds.h): names, rows in
// TEX_* order, the docs' table generated from it, and the GPU packing each row describes.
#include "texture_kinds.h"

#include "support/files.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

TEST(TextureKinds, RowsAreInKindOrderWithUniqueNames) {
  const auto& kinds = textureKinds();
  ASSERT_EQ(kinds.size(), size_t(TEX_KIND_COUNT - 1));
  for (size_t i = 0; i < kinds.size(); ++i) {
    EXPECT_EQ(int(kinds[i].kind), int(i) + 1);
    EXPECT_EQ(findTextureKind(kinds[i].name), &kinds[i]);
    EXPECT_EQ(textureKindName(kinds[i].kind), std::string(kinds[i].name));
    EXPECT_EQ(kinds[i].defaults.kind, kinds[i].kind) << kinds[i].name;
  }
  EXPECT_EQ(findTextureKind("checkers"), nullptr);
  EXPECT_STREQ(textureKindName(TextureKind::None), "none");
}

TEST(TextureKinds, SolidAndNoiseFlags) {
  EXPECT_FALSE(isSolidTexture(TextureKind::Checker));
  EXPECT_FALSE(isSolidTexture(TextureKind::Image));
  EXPECT_FALSE(isSolidTexture(TextureKind::None));
  EXPECT_TRUE(isSolidTexture(TextureKind::Wood));
  EXPECT_TRUE(textureKindInfo(TextureKind::Marble).needsNoise);
  EXPECT_FALSE(textureKindInfo(TextureKind::SolidChecker).needsNoise);
}

// The host's 2D kinds are the ones the kernel computes (u, v) for: both read COORD of
// shaders/kinds/kinds.h, the host through its row, the kernel through TEX_2D_KINDS.
TEST(TextureKinds, TwoDimensionalKindsMatchTheKernel) {
  uint32_t twoD = 0;
  for (const TextureKindInfo& info : textureKinds())
    if (!info.solid) twoD |= 1u << uint32_t(info.kind);
  EXPECT_EQ(twoD, uint32_t(TEX_2D_KINDS));
}

TEST(TextureKinds, RangesAcceptAndRefuse) {
  const TextureKey* octaves = findTextureKey("octaves");
  ASSERT_NE(octaves, nullptr);
  EXPECT_TRUE(inRange(octaves->range, 1));
  EXPECT_TRUE(inRange(octaves->range, 16));
  EXPECT_FALSE(inRange(octaves->range, 17));
  EXPECT_FALSE(inRange(octaves->range, 2.5));
  EXPECT_EQ(describeRange(octaves->range), "a whole number from 1 to 16");
  const TextureKey* scale = findTextureKey("scale");
  ASSERT_NE(scale, nullptr);
  EXPECT_FALSE(inRange(scale->range, 0.0));
  EXPECT_TRUE(inRange(scale->range, 1e-30));
  EXPECT_EQ(describeRange(scale->range), "> 0");
  EXPECT_EQ(describeRange(findTextureKey("strength")->range), "any");
}

// Each key lands in the slot its row names; kinds without a key leave that slot alone.
TEST(TextureKinds, PackingFollowsTheRows) {
  TextureDesc marble = defaultTexture(TextureKind::Marble);
  marble.scale = 3.0f;
  marble.strength = 5.0f;
  marble.octaves = 7;
  gpu::Material g{};
  packTexture(marble, &g);
  EXPECT_EQ(g.textureKind, uint32_t(TEX_MARBLE));
  EXPECT_EQ(g.params.x, 3.0f);
  EXPECT_EQ(g.params.y, 5.0f);
  EXPECT_EQ(g.octaves, 7u);
  EXPECT_EQ(glm::vec3(g.color1), marble.color1);
  TextureDesc checker = defaultTexture(TextureKind::Checker);
  checker.squares = 5.0f;
  gpu::Material c{};
  packTexture(checker, &c);
  EXPECT_EQ(c.params.z, 5.0f);
  EXPECT_EQ(glm::vec3(c.color2), checker.color2);
}

// docs/scene-format.md holds the table the rows make, verbatim.
TEST(TextureKinds, DocsTableMatchesTheRows) {
  std::string docs = readFile(kSourceDir + "/docs/scene-format.md");
  ASSERT_FALSE(docs.empty());
  std::string table = textureKindsMarkdown();
  EXPECT_NE(docs.find(table), std::string::npos)
      << "docs/scene-format.md lacks the texture table of host/scene/texture_kinds.cpp; it should read:\n" << table;
}
