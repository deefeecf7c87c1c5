// `raytex diff A B`: two image files compared (image_metrics.h, flip.h), reported as a table
// or one JSON object, the --fail-* limits checked. No Vulkan.
#pragma once

#include "output_plan.h"
#include "srgb.h"
#include "image_metrics.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// Largest linear float RGB image diff reads for each input (12 bytes a pixel): 256 MiB, 22.4
// Mpixel. The comparison holds the two images and the FLIP error map (4 bytes a pixel) and
// otherwise rows: its peak is under 31 bytes a pixel, about 680 MB for two such images
// (bench/diff.sh).
constexpr uint64_t kDiffMaxImageBytes = uint64_t(256) << 20;

// The largest linear channel difference that `raytex diff` does not count (--threshold): above
// the widest step between neighbouring 8-bit sRGB codes (1 - srgbToLinear(254 / 255) =
// 0.0089), so that rounding to 8 bits never counts as a difference.
constexpr double kDefaultDiffThreshold = 0.01;

struct DiffOptions {
  std::string reference, test;  // the two image files, A and B
  double threshold = kDefaultDiffThreshold;  // --threshold T
  std::string heatmap;  // --heatmap FILE: the FLIP error map as a PNG; empty: none
  std::optional<double> failRmse, failFlip, failPercent;  // --fail-rmse, --fail-flip, --fail-percent
  bool json = false;  // --json: one JSON object instead of the table
};

struct DiffReport {
  std::string reference, test;  // the paths compared
  int width = 0, height = 0;
  double threshold = kDefaultDiffThreshold;
  ImageMetrics metrics;
  double flip = 0.0;  // the mean FLIP error of the sRGB encodings (values clamped to [0, 1])
  FloatImage flipError;  // per pixel, 1 channel
};

// Reads both files (readLinearImage), refuses an image holding NaN or infinity and images of
// different sizes (ImageInputError naming both sizes), clamps both to [0, 1] when either is of low dynamic range, and measures.
DiffReport compareImageFiles(const DiffOptions& options);

// The report as lines of "name  value", and as one JSON object (keys in docs/cli.md).
std::string diffTable(const DiffReport& report);
std::string diffJson(const DiffReport& report);

// One line per --fail-* limit the report exceeds ("RMSE 0.02 exceeds --fail-rmse 0.01").
std::vector<std::string> exceededLimits(const DiffReport& report, const DiffOptions& options);

// Adds --heatmap to the plan's writes. Throws UsageError for standard output (-) or a regular
// file not named .png; whether it may replace what is there is checkPlan's.
void planHeatmap(OutputPlan& plan, const DiffOptions& options);

// What render --compare reads and writes besides the render (RenderOptions::alongside): the
// reference, which must be a regular file, and the heat map.
OutputPlan comparePlan(const DiffOptions& options);

// The whole command: the output plan checked (both images regular files, the heat map none of
// them, output_plan.h), compares, writes the heat map, prints the report to standard
// output and each exceeded limit to standard error. Returns 0, or 1 when a limit is exceeded.
int runDiff(const DiffOptions& options);
