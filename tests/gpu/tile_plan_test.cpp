// Tile kernels' plans (host/gpu/tile_kernels.h), on the host: which kinds a tile can show, the
// kernels chosen, and the order that gives every tile to exactly one kernel able to render it.
#include "gpu_scene.h"
#include "reference.h"
#include "support/sphere_field.h"
#include "texture_kinds.h"
#include "tile_kernels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

uint32_t bit(uint32_t kind) { return 1u << kind; }

// Every tile (of `columns` a row) is one kernel's exactly once, and that kernel holds the
// tile's kinds.
void expectEveryTileOnce(const TilePlan& plan, const std::vector<TextureKinds>& tiles, uint32_t columns) {
  EXPECT_LE(plan.kernels.size(), size_t(MAX_TILE_KERNELS));
  std::vector<int> seen(tiles.size(), 0);
  for (const TileKernel& k : plan.kernels) {
    EXPECT_FALSE(k.tiles.empty());
    for (uint32_t word : k.tiles) {
      const uint32_t x = word & 0xFFFFu, y = word >> 16;
      ASSERT_LT(x, columns);
      const size_t t = size_t(y) * columns + x;
      ASSERT_LT(t, tiles.size());
      ++seen[t];
      EXPECT_TRUE(k.kinds.covers(tiles[t])) << "tile " << t;
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(tiles.size()));
}

}  // namespace

// Tiles showing only the floor get a kernel without the spheres' kinds; tiles with a sphere keep
// its kind; the plan hands every tile to one kernel.
TEST(TilePlan, FloorTilesDropTheSpheresKinds) {
  const TextureKinds floor{0, bit(TEX_CHECKER)}, marble{bit(TEX_MARBLE), bit(TEX_CHECKER)};
  std::vector<TextureKinds> tiles(100, floor);
  for (int t : {44, 45, 54, 55}) tiles[size_t(t)] = marble;
  const std::vector<TextureKinds> family = chooseTileKernels(tiles, marble);
  ASSERT_EQ(family.size(), 2u);
  EXPECT_EQ(family[0], marble);
  EXPECT_EQ(family[1], floor);
  const TilePlan plan = assignTiles(family, tiles, 10);
  ASSERT_EQ(plan.kernels.size(), 2u);
  EXPECT_EQ(plan.kernels[0].tiles, (std::vector<uint32_t>{4 | 4 << 16, 5 | 4 << 16, 4 | 5 << 16, 5 | 5 << 16}));
  EXPECT_EQ(plan.kernels[1].tiles.size(), 96u);
  expectEveryTileOnce(plan, tiles, 10);
  EXPECT_DOUBLE_EQ(plan.savedInstructions,
                   TILE_SIZE * TILE_SIZE * (96.0 * kindsCost({bit(TEX_MARBLE), 0}) - 100.0 * kTileOrderCost));
}

// One set for every tile: one kernel, which saves nothing, so renders keep the one kernel.
TEST(TilePlan, OneSetSavesNothing) {
  const TextureKinds all{bit(TEX_NOISE), bit(TEX_CHECKER)};
  const std::vector<TextureKinds> tiles(50, all);
  EXPECT_EQ(chooseTileKernels(tiles, all).size(), 1u);
  const TilePlan plan = assignTiles(chooseTileKernels(tiles, all), tiles, 5);
  ASSERT_EQ(plan.kernels.size(), 1u);
  expectEveryTileOnce(plan, tiles, 5);
  EXPECT_LT(plan.savedInstructions, 0.0);  // the tile order's cost
  EXPECT_FALSE(tileKernelsPay(plan, INFINITY));
  EXPECT_TRUE(assignTiles({all}, {}, 5).kernels.empty());
}

// Many sets: at most MAX_TILE_KERNELS kernels, the rare sets falling back to the full one.
TEST(TilePlan, ManySetsKeepToTheKernelLimit) {
  const uint32_t noiseKinds[] = {TEX_NOISE, TEX_MARBLE, TEX_WOOD, TEX_TURBULENCE, TEX_DTURBULENCE, TEX_IMAGE};
  TextureKinds all{0, bit(TEX_CHECKER)};
  for (uint32_t k : noiseKinds) all.sphere |= bit(k);
  std::vector<TextureKinds> tiles(600, TextureKinds{0, bit(TEX_CHECKER)});
  for (size_t t = 0; t < 300; ++t) tiles[t].sphere = bit(noiseKinds[t % 6]) | (t % 7 == 0 ? bit(TEX_WOOD) : 0u);
  const TilePlan plan = assignTiles(chooseTileKernels(tiles, all), tiles, 30);
  EXPECT_EQ(plan.kernels.size(), size_t(MAX_TILE_KERNELS));
  expectEveryTileOnce(plan, tiles, 30);
  EXPECT_GT(plan.savedInstructions, 0.0);
}

// The viewer's two sets: the floor's kinds alone, for the tiles no sphere reaches, and all.
TEST(TilePlan, TheViewersSetsDoNotDependOnTheCamera) {
  const TextureKinds all{bit(TEX_WOOD) | bit(TEX_IMAGE), bit(TEX_CHECKER)};
  const std::vector<TextureKinds> family = sphereFreeTileKernels(all);
  ASSERT_EQ(family.size(), 2u);
  EXPECT_EQ(family[0], all);
  EXPECT_EQ(family[1], (TextureKinds{0, bit(TEX_CHECKER)}));
}

// Pipelines pay only over enough samples: a plan saving a little needs many frames.
TEST(TilePlan, PipelinesPayOverEnoughSamples) {
  const TextureKinds floor{0, bit(TEX_CHECKER)}, marble{bit(TEX_MARBLE), bit(TEX_CHECKER)};
  std::vector<TextureKinds> tiles(240 * 135, floor);  // 1920 x 1080
  tiles[0] = marble;
  const TilePlan plan = assignTiles(chooseTileKernels(tiles, marble), tiles, 240);
  ASSERT_EQ(plan.kernels.size(), 2u);
  EXPECT_FALSE(tileKernelsPay(plan, 1.0));
  EXPECT_TRUE(tileKernelsPay(plan, 1000.0));
  EXPECT_TRUE(tileKernelsPay(plan, INFINITY));
}

// The viewer's pair of kernels only where a tile without spheres saves more than the order costs:
// a noise kind's code, or a sphere's latitude and longitude, but not a solid checker's few lines.
TEST(TilePlan, TheViewerSplitsWhereTheFloorsTilesSave) {
  EXPECT_TRUE(sphereFreeTilesSave({bit(TEX_MARBLE), bit(TEX_CHECKER)}));
  EXPECT_TRUE(sphereFreeTilesSave({bit(TEX_CHECKER), bit(TEX_CHECKER)}));
  EXPECT_FALSE(sphereFreeTilesSave({bit(TEX_SOLID_CHECKER), bit(TEX_CHECKER)}));
}

// The kinds a tile can show hold the kind of every sphere the float64 reference's ray hits in
// it; tiles far from every sphere show the floor's alone.
TEST(TilePlan, TileKindsHoldWhatThePixelsHit) {
  const Scene scene = field(60, "(0, 1, 4)");
  const uint32_t w = 160, h = 90;
  const GpuScene g = buildGpuScene(scene, w, h);
  const std::vector<TextureKinds> kinds = tileKinds(g);
  ASSERT_EQ(kinds.size(), size_t(g.tiles.columns) * g.tiles.rows);
  int hits = 0;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const ReferenceHit hit = referenceClosestHit(scene, scene.camera.eye,
                                                   referenceRayDirection(scene.camera, int(w), int(h), int(x), int(y)), false);
      const TextureKinds& tile = kinds[(y / TILE_SIZE) * g.tiles.columns + x / TILE_SIZE];
      EXPECT_EQ(tile.plane, bit(TEX_CHECKER));
      if (hit.kind != HIT_SPHERE) continue;
      ++hits;
      const uint32_t kind = uint32_t(scene.materials[size_t(scene.spheres[size_t(hit.index)].material)].texture.kind);
      EXPECT_TRUE(tile.sphere & bit(kind)) << x << ", " << y;
    }
  EXPECT_GT(hits, 100);
  EXPECT_GT(std::count(kinds.begin(), kinds.end(), TextureKinds{0, bit(TEX_CHECKER)}), std::ptrdiff_t(kinds.size() / 4));
}
