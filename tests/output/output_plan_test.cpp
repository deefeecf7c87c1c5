// The output plan (output_plan.h): no write may be a file the command reads or another write,
// a pass file never lands beside a device, names fit their directory, and every refusal names
// both paths.
#include "error.h"
#include "output_plan.h"
#include "parser.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <filesystem>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// The message checkPlan throws for `plan`, "" when it accepts it; `kind` receives the error's kind.
std::string planRefusal(const OutputPlan& plan, ErrorKind* kind = nullptr) {
  try {
    checkPlan(plan);
  } catch (const Error& e) {
    if (kind) *kind = e.kind;
    return e.what();
  }
  return "";
}

OutputPlan writing(const fs::path& path, bool named = true) {
  OutputPlan plan;
  plan.writes.push_back({path.string(), "the image", named, ""});
  return plan;
}

}  // namespace

TEST(OutputPlan, TheSceneItsIncludesAndImagesAreNotOutputs) {
  fs::path dir = freshTempDir("output_plan_scene");
  writeFile(dir / "inc.cfg", "material m { texture = image { file = \"tex.png\"; } }\n");
  writeFile(dir / "tex.png", "not read here");
  writeFile(dir / "s.cfg", "#include \"inc.cfg\"\nsphere { m; }\n");
  const Scene scene = parseSceneFile((dir / "s.cfg").string());
  auto clash = [&](const fs::path& p) {
    OutputPlan plan = writing(p);
    planSceneReads(plan, scene, "the scene");
    return planRefusal(plan);
  };
  const std::string s = (dir / "s.cfg").string(), inc = (dir / "inc.cfg").string(), tex = (dir / "tex.png").string();
  EXPECT_EQ(clash(s), "refusing to write '" + s + "': it is the scene file ('" + s + "')");
  EXPECT_EQ(clash(inc), "refusing to write '" + inc + "': it is a file the scene includes ('" + inc + "')");
  EXPECT_EQ(clash(tex), "refusing to write '" + tex + "': it is an image the scene uses ('" + tex + "')");
  fs::create_hard_link(dir / "s.cfg", dir / "hard.cfg");  // same inode, another name
  fs::create_symlink("inc.cfg", dir / "soft.png");
  EXPECT_EQ(clash(dir / "hard.cfg"), "refusing to write '" + (dir / "hard.cfg").string() +
                                         "': it is the scene file ('" + s + "')");
  EXPECT_NE(clash(dir / "soft.png"), "");
  writeFile(dir / "other.png", "x");
  EXPECT_EQ(clash(dir / "other.png"), "");
  EXPECT_EQ(clash(dir / "new.png"), "");
  EXPECT_EQ(clash("-"), "");
}

TEST(OutputPlan, TwoWritesOfOneFileAreRefusedWhetherOrNotItExists) {
  fs::path dir = freshTempDir("output_plan_twice");
  OutputPlan plan;
  plan.writes.push_back({(dir / "a.png").string(), "the image of 'x.cfg'", false, ""});
  plan.writes.push_back({(dir / "a.png").string(), "the albedo pass of 'y.cfg'", false, ""});
  EXPECT_EQ(planRefusal(plan), "refusing to write '" + (dir / "a.png").string() +
                               "' twice: it is the image of 'x.cfg' and the albedo pass of 'y.cfg'");
  plan.writes[1].path = (dir / "." / "a.png").string();  // another spelling of a new file
  EXPECT_NE(planRefusal(plan).find("they are one file"), std::string::npos) << planRefusal(plan);
  writeFile(dir / "b.png", "old");
  fs::create_symlink("b.png", dir / "link.png");
  plan.writes[0].path = (dir / "b.png").string();
  plan.writes[1].path = (dir / "link.png").string();
  EXPECT_EQ(planRefusal(plan), "refusing to write '" + (dir / "b.png").string() + "' and '" + (dir / "link.png").string() +
                               "': they are one file, the image of 'x.cfg' and the albedo pass of 'y.cfg'");
  plan.writes[1].path = (dir / "c.png").string();
  EXPECT_EQ(planRefusal(plan), "");
}

TEST(OutputPlan, AWriteThatIsAReadIsRefusedEvenBeforeEitherExists) {
  fs::path dir = freshTempDir("output_plan_read");
  OutputPlan plan = writing(dir / "ref.png");
  plan.reads.push_back({(dir / "ref.png").string(), "the reference image --compare reads", true});
  EXPECT_EQ(planRefusal(plan), "refusing to write '" + (dir / "ref.png").string() +
                               "': it is the reference image --compare reads ('" + (dir / "ref.png").string() + "')");
  writeFile(dir / "ref.png", "golden");
  EXPECT_NE(planRefusal(plan), "");
  EXPECT_EQ(readFile(dir / "ref.png"), "golden");
}

TEST(OutputPlan, AReadThatMustBeARegularFileIsCheckedFirst) {
  fs::path dir = freshTempDir("output_plan_fifo");
  ASSERT_EQ(mkfifo((dir / "f.png").c_str(), 0600), 0);
  OutputPlan plan;
  plan.reads.push_back({(dir / "f.png").string(), "an image compared", true});
  ErrorKind kind = ErrorKind::Internal;
  EXPECT_EQ(planRefusal(plan, &kind), "cannot open image '" + (dir / "f.png").string() + "': not a regular file");
  EXPECT_EQ(kind, ErrorKind::ImageInput);
  plan.reads[0].path = (dir / "none.png").string();
  EXPECT_EQ(planRefusal(plan), "cannot open image '" + (dir / "none.png").string() + "': No such file or directory");
}

TEST(OutputPlan, PassFilesNeverGoBesideADeviceOrFifoNorOntoOne) {
  fs::path dir = freshTempDir("output_plan_device");
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  OutputPlan plan = writing(dir / "fifo");
  EXPECT_EQ(planRefusal(plan), "");  // named: written through
  plan.writes.push_back({(dir / "fifo.normal.pfm").string(), "the normal pass", false, (dir / "fifo").string()});
  EXPECT_NE(planRefusal(plan).find("beside '" + (dir / "fifo").string() + "', which is not a regular file"),
            std::string::npos)
      << planRefusal(plan);
  ASSERT_EQ(mkfifo((dir / "x.png").c_str(), 0600), 0);
  ErrorKind kind = ErrorKind::Internal;
  EXPECT_NE(planRefusal(writing(dir / "x.png", false), &kind).find("it exists and is not a regular file"), std::string::npos);
  EXPECT_EQ(kind, ErrorKind::Usage);
  if (mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {  // root only
    OutputPlan twice = writing(dir / "null");
    twice.writes.push_back({(dir / "null").string(), "the heat map", true, ""});
    EXPECT_EQ(planRefusal(twice), "");  // one null device takes both
  }
}

TEST(OutputPlan, ANameOverTheDirectorysLimitAndAMissingDirectoryAreRefused) {
  fs::path dir = freshTempDir("output_plan_names");
  ErrorKind kind = ErrorKind::Internal;
  const std::string longName(256, 'n');
  EXPECT_NE(planRefusal(writing(dir / longName), &kind).find("its name is 256 bytes, more than the 255"), std::string::npos);
  EXPECT_EQ(kind, ErrorKind::Usage);
  EXPECT_EQ(planRefusal(writing(dir / std::string(255, 'n'))), "");
  EXPECT_EQ(planRefusal(writing(dir / "none" / "a.png"), &kind),
            "cannot write '" + (dir / "none" / "a.png").string() + "': No such file or directory");
  EXPECT_EQ(kind, ErrorKind::Io);
  fs::create_directory(dir / "d.png");
  EXPECT_EQ(planRefusal(writing(dir / "d.png"), &kind), "cannot write '" + (dir / "d.png").string() + "': Is a directory");
  EXPECT_EQ(kind, ErrorKind::Io);
}
