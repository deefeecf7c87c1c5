// The output formats' table (host/output/output_formats.h): each row's word and extension, its
// writer and its reader, which read back what the writer wrote.
#include "output_formats.h"

#include "error.h"
#include "image_file.h"
#include "srgb.h"
#include "support/band_images.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

TEST(OutputFormats, RowsAreInFormatOrderWithDistinctWords) {
  std::set<std::string> words;
  for (size_t i = 0; i < outputFormats().size(); ++i) {
    const OutputFormatInfo& row = outputFormats()[i];
    EXPECT_EQ(int(row.format), int(i));
    EXPECT_TRUE(words.insert(row.name).second) << row.name;
    EXPECT_EQ(findOutputFormat(row.name), &row);
    std::string upper = row.name;
    for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_EQ(outputFormatFor("dir/image." + upper), row.format) << row.name;
    ASSERT_NE(row.writer, nullptr);
    ASSERT_NE(row.reader, nullptr);
  }
  EXPECT_EQ(outputFormatWords(), "png, exr or pfm");
  EXPECT_EQ(outputExtensions(), ".png, .exr, .pfm");
  EXPECT_EQ(findOutputFormat("jpg"), nullptr);
  try {
    outputFormatFor("image.jpg");
    ADD_FAILURE() << "image.jpg has a format";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "'image.jpg': unknown output format (supported: .png, .exr, .pfm)");
  }
}

// Every row's reader gives back its writer's image: exactly for the float formats, within the
// 8-bit sRGB step (values clamped to [0, 1]) for PNG.
TEST(OutputFormats, EachReaderReadsBackWhatItsWriterWrote) {
  const auto dir = freshTempDir("output_formats");
  const BandImage image = bandImage(7, 5, {});
  for (const OutputFormatInfo& row : outputFormats()) {
    const std::string path = (dir / (std::string("image.") + row.name)).string();
    writeBandImage(bandSpec(path, row.format, image, {}), image, 2, BandOrder::Shuffled);
    const LinearImage back = row.reader(path, 1u << 20);
    ASSERT_EQ(back.image.width, image.width) << row.name;
    ASSERT_EQ(back.image.height, image.height) << row.name;
    ASSERT_EQ(back.image.channels, 3) << row.name;
    double worst = 0.0;
    for (size_t p = 0; p < size_t(image.width * image.height); ++p)
      for (size_t c = 0; c < 3; ++c) {
        const double written = image.rgba[4 * p + c], read = back.image.pixels[3 * p + c];
        const double expected = back.lowDynamicRange ? std::clamp(written, 0.0, 1.0) : written;
        // Compared where PNG quantises: in sRGB, whose steps are 1/255.
        const double error = back.lowDynamicRange ? std::fabs(linearToSrgb(read) - linearToSrgb(expected))
                                                  : std::fabs(read - expected);
        worst = std::max(worst, error);
      }
    EXPECT_LE(worst, back.lowDynamicRange ? 0.5 / 255.0 + 1e-6 : 0.0) << row.name;
    EXPECT_EQ(readLinearImage(path, 1u << 20).image.pixels, back.image.pixels) << row.name;
  }
}
