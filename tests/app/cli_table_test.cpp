// The command line's table (host/app/cli.cpp): parsing of both option forms, refusals, and the
// reference in docs/cli.md, which must equal the table.
#include "cli.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace {

const std::string kCliDoc = kSourceDir + "/docs/cli.md";
const std::string kBegin = "<!-- option table: begin -->\n";
const std::string kEnd = "<!-- option table: end -->\n";

// The Usage error's message of parsing `args`, or "" when they parse.
std::string refusal(const std::vector<std::string>& args) {
  try {
    parseCli(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CliTable, TheReferenceInDocsIsTheTable) {
  std::string doc = readFile(kCliDoc);
  size_t begin = doc.find(kBegin), end = doc.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << kCliDoc << " lacks " << kBegin;
  ASSERT_NE(end, std::string::npos) << kCliDoc << " lacks " << kEnd;
  begin += kBegin.size();
  const std::string table = optionReference();
  if (getenv("RAYTEX_UPDATE_GOLDENS")) {
    doc.replace(begin, end - begin, table);
    std::ofstream(kCliDoc, std::ios::binary) << doc;
    return;
  }
  EXPECT_EQ(doc.substr(begin, end - begin), table)
      << "docs/cli.md differs from host/app/cli.cpp's table; RAYTEX_UPDATE_GOLDENS=1 rewrites its reference";
}

TEST(CliTable, LongOptionsTakeTheirValueAfterASpaceOrAnEqualsSign) {
  CliArgs spaced = parseCli({"render", "s.cfg", "--width", "320", "--filter", "box", "-o", "a.png"});
  CliArgs joined = parseCli({"render", "s.cfg", "--width=320", "--filter=box", "--output=a.png"});
  for (const CliArgs& cli : {spaced, joined}) {
    EXPECT_EQ(cli.command, CliCommand::Render);
    EXPECT_EQ(cli.render.scene, "s.cfg");
    EXPECT_EQ(cli.render.width.value_or(0), 320u);
    EXPECT_EQ(cli.render.filter, TextureFilter::Box);
    EXPECT_EQ(cli.render.output, "a.png");
  }
  EXPECT_EQ(parseCli({"bench", "s.cfg", "--runs=7"}).bench.runs, 7u);
  EXPECT_EQ(parseCli({"render", "s.cfg", "--allow-read=a=b"}).render.allowRead.at(0), "a=b");
  EXPECT_EQ(refusal({"render", "s.cfg", "--width="}), "--width expects an integer from 1 to 16384, got ''");
  EXPECT_EQ(refusal({"render", "s.cfg", "--stats=1"}), "--stats takes no value");
  EXPECT_EQ(refusal({"render", "s.cfg", "--width"}), "--width needs a value");
}

TEST(CliTable, AnOptionOfAnotherCommandIsRefusedByName) {
  EXPECT_EQ(refusal({"render", "s.cfg", "--frames", "3"}), "--frames is an option of raytex view, not of render");
  EXPECT_EQ(refusal({"view", "s.cfg", "--reference"}), "--reference is an option of raytex render, not of view");
  EXPECT_EQ(refusal({"bench", "s.cfg", "--stats"}), "--stats is an option of raytex render and view, not of bench");
  EXPECT_EQ(refusal({"render", "s.cfg", "--fast"}), "unknown option '--fast' (try raytex --help)");
}

TEST(CliTable, AnOptionWithoutEffectIsRefused) {
  EXPECT_EQ(refusal({"render", "s.cfg", "--reference", "--filter", "box"}),
            "--filter has no effect with --reference: the reference samples each texture at its hit point");
  EXPECT_EQ(refusal({"render", "s.cfg", "--device=0", "--reference"}),
            "--device has no effect with --reference: the reference renders on the CPU");
  EXPECT_EQ(refusal({"render", "s.cfg", "--reference", "--validate"}),
            "--validate has no effect with --reference: the reference uses no Vulkan");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "-", "--stats"}),
            "--stats prints to standard output, which -o - fills with the PNG");
  EXPECT_EQ(refusal({"view", "s.cfg", "-o", "-"}), "-o - (standard output) is for raytex render; bench and view write files");
  EXPECT_EQ(refusal({"bench", "s.cfg", "-o=-"}), "unknown option '-o=-' (try raytex --help)");
  EXPECT_EQ(refusal({"render", "s.cfg", "--reference", "--spp", "4", "--stats"}), "");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "-"}), "");
}

TEST(CliTable, EveryOptionIsInTheHelp) {
  const std::string help = usageText();
  const std::string reference = optionReference();
  size_t rows = 0;
  for (size_t at = reference.find("\n| `"); at != std::string::npos; at = reference.find("\n| `", at + 1)) {
    ++rows;
    size_t nameEnd = reference.find('`', at + 4);
    const std::string name = reference.substr(at + 4, nameEnd - at - 4);
    EXPECT_NE(help.find(name), std::string::npos) << name;
  }
  EXPECT_GE(rows, 14u);
}

TEST(CliTable, OutputFormatOptionsApplyToTheirFormatOnly) {
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "x.png", "--depth", "16"}), "");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "X.PNG", "--depth=16"}), "");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "x.exr", "--depth", "16"}), "--depth applies to a PNG output");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "x.png", "--depth", "12"}), "--depth expects 8 or 16, got '12'");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "x.exr", "--half"}), "");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "d/", "--format", "exr", "--half"}), "");
  EXPECT_EQ(refusal({"render", "s.cfg", "-o", "x.pfm", "--half"}), "--half applies to an EXR output");
  EXPECT_EQ(refusal({"render", "s.cfg", "--metadata", "all"}), "--metadata expects basic or full, got 'all'");
  EXPECT_TRUE(parseCli({"render", "s.cfg", "--metadata", "full"}).render.fullMetadata);
}

TEST(CliTable, PassesAreNamedAndNeedFilesAndTheBoxFilterWhereTheyComeFromIt) {
  const CliArgs cli = parseCli({"render", "s.cfg", "-o", "x.exr", "--aov", "depth,uv,depth"});
  ASSERT_EQ(cli.render.passes.size(), 2u);
  EXPECT_EQ(cli.render.passes[0], Pass::Uv);
  EXPECT_EQ(cli.render.passes[1], Pass::Depth);
  EXPECT_EQ(refusal({"render", "s.cfg", "--aov", "uv,colour"}),
            "--aov: unknown pass 'colour' (passes: uv, normal, depth, position, albedo, footprint, lod, octaves)");
  EXPECT_NE(refusal({"render", "s.cfg", "-o", "-", "--aov", "uv"}), "");
  EXPECT_NE(refusal({"render", "s.cfg", "--reference", "--aov", "uv"}), "");
  EXPECT_NE(refusal({"view", "s.cfg", "--aov", "uv"}), "");
  RenderOptions options = parseCli({"render", "s.cfg", "--aov", "lod"}).render;
  EXPECT_THROW(resolveJob(options, RenderSettings{}, 1), UsageError);
  options.filter = TextureFilter::Box;
  EXPECT_NO_THROW(resolveJob(options, RenderSettings{}, 1));
  options.filter = TextureFilter::Coverage;  // the box kernel with edges: its passes
  EXPECT_NO_THROW(resolveJob(options, RenderSettings{}, 1));
}

TEST(CliTable, CoverageIsAFilterAtAnySampleCount) {
  EXPECT_EQ(parseCli({"render", "s.cfg", "--filter", "coverage"}).render.filter, TextureFilter::Coverage);
  EXPECT_EQ(refusal({"render", "s.cfg", "--filter", "cone"}),
            "--filter expects point, box or coverage, got 'cone'");
  RenderOptions options = parseCli({"render", "s.cfg", "--filter", "coverage", "--spp", "16"}).render;
  const RenderJob job = resolveJob(options, RenderSettings{}, 1);
  EXPECT_EQ(job.filter, TextureFilter::Coverage);
  EXPECT_EQ(job.samplesPerSide, 4u);
  options = parseCli({"view", "s.cfg", "--filter", "coverage"}).render;
  EXPECT_EQ(resolveJob(options, RenderSettings{}, 64).filter, TextureFilter::Coverage);
  RenderSettings scene;
  scene.filter = TextureFilter::Coverage;
  options = parseCli({"render", "s.cfg"}).render;
  EXPECT_EQ(resolveJob(options, scene, 1).filter, TextureFilter::Coverage);
  options.filter = TextureFilter::Point;  // the flag over the render block
  EXPECT_EQ(resolveJob(options, scene, 1).filter, TextureFilter::Point);
}

TEST(CliTable, ImageFiltersComeWithTheBoxOrCoverageFilter) {
  EXPECT_EQ(refusal({"render", "s.cfg", "--image-filter", "box"}),
            "--image-filter expects anisotropic, trilinear, bilinear, ewa or stochastic, got 'box'");
  RenderOptions options = parseCli({"render", "s.cfg", "--image-filter", "ewa", "--filter", "box"}).render;
  EXPECT_EQ(resolveJob(options, RenderSettings{}, 1).imageFilter, ImageFilter::Ewa);
  options.filter = TextureFilter::Point;
  try {
    resolveJob(options, RenderSettings{}, 1);
    ADD_FAILURE() << "--image-filter ewa with --filter point was accepted";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "image filter ewa filters over the footprint: add --filter box or coverage (point looks "
                           "images up at the hit)");
  }
  RenderSettings scene;  // the render block's, under the flag's
  scene.filter = TextureFilter::Coverage;
  scene.imageFilter = ImageFilter::Stochastic;
  options = parseCli({"render", "s.cfg"}).render;
  EXPECT_EQ(resolveJob(options, scene, 1).imageFilter, ImageFilter::Stochastic);
  options.imageFilter = ImageFilter::Trilinear;
  EXPECT_EQ(resolveJob(options, scene, 1).imageFilter, ImageFilter::Trilinear);
  EXPECT_EQ(resolveJob(parseCli({"render", "s.cfg"}).render, RenderSettings{}, 1).imageFilter, ImageFilter::Anisotropic);
}

TEST(CliTable, DiffTakesTwoImagesAndOnlyItsOwnOptions) {
  const CliArgs cli = parseCli({"diff", "a.png", "--threshold=0.02", "b.png", "--heatmap", "h.png", "--fail-rmse",
                                "0.1", "--fail-flip", "0.05", "--fail-percent", "2.5", "--json"});
  EXPECT_EQ(cli.command, CliCommand::Diff);
  EXPECT_EQ(cli.diff.reference, "a.png");
  EXPECT_EQ(cli.diff.test, "b.png");
  EXPECT_EQ(cli.diff.threshold, 0.02);
  EXPECT_EQ(cli.diff.heatmap, "h.png");
  EXPECT_EQ(cli.diff.failRmse.value_or(-1), 0.1);
  EXPECT_EQ(cli.diff.failFlip.value_or(-1), 0.05);
  EXPECT_EQ(cli.diff.failPercent.value_or(-1), 2.5);
  EXPECT_TRUE(cli.diff.json);
  EXPECT_EQ(parseCli({"diff", "a.png", "b.png"}).diff.threshold, kDefaultDiffThreshold);
  EXPECT_FALSE(parseCli({"diff", "a.png", "b.png"}).diff.failRmse.has_value());
  EXPECT_EQ(refusal({"diff", "a.png"}), "diff needs two images (e.g. raytex diff a.png b.png)");
  EXPECT_EQ(refusal({"diff", "a.png", "b.png", "c.png"}), "diff compares two images, got a third ('c.png')");
  EXPECT_EQ(refusal({"diff", "a.png", "b.png", "--width", "3"}),
            "--width is an option of raytex render, view and bench, not of diff");
  EXPECT_EQ(refusal({"diff", "a.png", "b.png", "-o", "x.png"}),
            "-o is an option of raytex render, view and bench, not of diff");
  EXPECT_EQ(refusal({"render", "s.cfg", "--threshold", "0.1"}),
            "--threshold applies to raytex diff and to render with --compare");
  EXPECT_EQ(refusal({"render", "s.cfg", "--compare", "r.png", "--threshold", "0.1"}), "");
  EXPECT_EQ(refusal({"bench", "s.cfg", "--fail-flip", "0.1"}), "--fail-flip is an option of raytex render and diff, not of bench");
  EXPECT_EQ(refusal({"diff", "a.png", "b.png", "--fail-flip", "2"}), "--fail-flip expects a number from 0 to 1, got '2'");
  EXPECT_EQ(refusal({"diff", "a.png", "b.png", "--threshold", "nan"}),
            "--threshold expects a number from 0 to 1e+30, got 'nan'");
  EXPECT_EQ(refusal({"diff", "a.png", "b.png", "--fail-percent", "-1"}),
            "--fail-percent expects a number from 0 to 100, got '-1'");
}
