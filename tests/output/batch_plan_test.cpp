// Where each scene of a batch writes (batch.h): names from the scene's file name, bad
// directories refused before anything renders (clashes: output_plan_test.cpp).
#include "batch.h"
#include "error.h"
#include "support/files.h"

#include <gtest/gtest.h>

TEST(BatchPlan, EachSceneWritesItsNameWithTheFormatsExtension) {
  const std::string dir = freshTempDir("batch_plan").string() + "/";
  const std::vector<BatchItem> items = planBatch({"scenes/marble.cfg", "a.b.cfg", "noext", "x/.hidden"}, dir, ".exr");
  ASSERT_EQ(items.size(), 4u);
  EXPECT_EQ(items[0].scene, "scenes/marble.cfg");
  EXPECT_EQ(items[0].output, dir + "marble.exr");
  EXPECT_EQ(items[1].output, dir + "a.b.exr");
  EXPECT_EQ(items[2].output, dir + "noext.exr");
  EXPECT_EQ(items[3].output, dir + ".hidden.exr");
}

TEST(BatchPlan, AMissingDirectoryOrAFileIsRefused) {
  const std::filesystem::path dir = freshTempDir("batch_plan_dir");
  EXPECT_THROW(planBatch({"s.cfg"}, (dir / "none").string() + "/", ".png"), UsageError);
  writeFile(dir / "file", "x");
  try {
    planBatch({"s.cfg"}, (dir / "file").string() + "/", ".png");
    FAIL() << "a file taken for a directory";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("not a directory"), std::string::npos) << e.what();
  }
}

TEST(BatchPlan, OnlyANameEndingInSlashIsADirectory) {
  EXPECT_TRUE(isOutputDirectory("out/"));
  EXPECT_FALSE(isOutputDirectory("out"));
  EXPECT_FALSE(isOutputDirectory("-"));
  EXPECT_FALSE(isOutputDirectory(""));
}
