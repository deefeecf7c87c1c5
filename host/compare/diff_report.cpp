#include "diff_report.h"

#include "error.h"
#include "flip.h"
#include "output_formats.h"
#include "atomic_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <malloc.h>
#include <sys/stat.h>

namespace {

std::string sizeText(const FloatImage& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// The length of the well-formed UTF-8 sequence that starts at s[i] (Unicode's table 3-7: no
// overlong forms, no surrogates, nothing past U+10FFFF), or 0 where none does.
size_t utf8SequenceLength(const std::string& s, size_t i) {
  const unsigned char lead = static_cast<unsigned char>(s[i]);
  if (lead < 0x80) return 1;
  const size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                        : lead >= 0xE0 && lead <= 0xEF ? 3
                        : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                       : 0;  // 80..C1 and F5..FF lead nothing
  if (length == 0 || i + length > s.size()) return 0;
  // The second byte's range (later bytes take 80..BF), narrowed after four leads.
  unsigned char low = 0x80, high = 0xBF;
  if (lead == 0xE0) low = 0xA0;   // below: overlong
  if (lead == 0xED) high = 0x9F;  // above: surrogates
  if (lead == 0xF0) low = 0x90;   // below: overlong
  if (lead == 0xF4) high = 0x8F;  // above: past U+10FFFF
  for (size_t k = 1; k < length; ++k) {
    const unsigned char c = static_cast<unsigned char>(s[i + k]);
    if (c < (k == 1 ? low : 0x80) || c > (k == 1 ? high : 0xBF)) return 0;
  }
  return length;
}

// A JSON string literal: paths may hold quotes, backslashes and control characters, and any
// bytes; each byte that is not part of well-formed UTF-8 becomes U+FFFD (the replacement
// character), so the JSON is always valid UTF-8.
std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (size_t i = 0; i < s.size();) {
    const size_t length = utf8SequenceLength(s, i);
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (length == 0) {
      out += "\\ufffd";
      ++i;
      continue;
    }
    if (c < 0x20) {
      char buf[8];
      snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      if (c == '"' || c == '\\') out += '\\';
      out.append(s, i, length);
    }
    i += length;
  }
  return out + "\"";
}

// A number as JSON: null where it is not finite (PSNR of equal images, SSIM of a small one).
std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string formatted(const char* format, double v) {
  char buf[64];
  snprintf(buf, sizeof buf, format, v);
  return buf;
}

// Refuses an image holding NaN or infinity: no measure of a difference is defined there.
void requireFinite(const std::string& path, const FloatImage& image) {
  const size_t bad = nonFiniteCount(image);
  if (bad > 0)
    throw ImageInputError("image '" + path + "' holds " + std::to_string(bad) +
                          " values that are not finite: raytex diff compares finite values");
}

}  // namespace

DiffReport compareImageFiles(const DiffOptions& options) {
  LinearImage reference = readLinearImage(options.reference, kDiffMaxImageBytes);
  LinearImage test = readLinearImage(options.test, kDiffMaxImageBytes);
  requireFinite(options.reference, reference.image);
  requireFinite(options.test, test.image);
  if (reference.image.width != test.image.width || reference.image.height != test.image.height)
    throw ImageInputError("'" + options.reference + "' is " + sizeText(reference.image) + " but '" + options.test +
                          "' is " + sizeText(test.image) + ": raytex diff compares images of one size");
  clampForComparison(reference, test);
  DiffReport report;
  report.reference = options.reference;
  report.test = options.test;
  report.width = reference.image.width;
  report.height = reference.image.height;
  report.threshold = options.threshold;
  report.metrics = measureImages(reference.image, test.image, options.threshold);
  // The sRGB encodings a row at a time: no copy of either image.
  const FloatImage &a = reference.image, &b = test.image;
  report.flipError =
      flipErrorMap(a.width, a.height, [&a](int y, int x0, int x1, float* rgb) { linearToSrgbRow(a, y, x0, x1, rgb); },
                   [&b](int y, int x0, int x1, float* rgb) { linearToSrgbRow(b, y, x0, x1, rgb); });
  report.flip = flipMean(report.flipError);
  return report;
}

std::string diffTable(const DiffReport& r) {
  const ImageMetrics& m = r.metrics;
  std::string out = "A          " + r.reference + " (" + std::to_string(r.width) + "x" + std::to_string(r.height) +
                    ")\nB          " + r.test + "\n";
  out += "RMSE       " + formatted("%.6g", m.rmse) + " (linear)\n";
  out += "PSNR       " + (std::isfinite(m.psnr) ? formatted("%.2f dB", m.psnr) : "inf (equal)") + "\n";
  out += "SSIM       " + (std::isfinite(m.ssim) ? formatted("%.5f", m.ssim) : "n/a (under 7x7 pixels)") + "\n";
  out += "FLIP       " + formatted("%.5f", r.flip) + " (mean)\n";
  out += "max diff   " + formatted("%.6g", m.maxDifference) + " (linear)\n";
  out += "over T     " + formatted("%.3f%% of the pixels", 100.0 * m.shareOver) +
         formatted(" (T = %g, linear)\n", r.threshold);
  return out;
}

std::string diffJson(const DiffReport& r) {
  const ImageMetrics& m = r.metrics;
  return "{\"a\": " + jsonString(r.reference) + ", \"b\": " + jsonString(r.test) +
         ", \"width\": " + std::to_string(r.width) + ", \"height\": " + std::to_string(r.height) +
         ", \"rmse\": " + jsonNumber(m.rmse) + ", \"psnr\": " + jsonNumber(m.psnr) +
         ", \"ssim\": " + jsonNumber(m.ssim) + ", \"flip\": " + jsonNumber(r.flip) +
         ", \"max_difference\": " + jsonNumber(m.maxDifference) + ", \"threshold\": " + jsonNumber(r.threshold) +
         ", \"percent_over_threshold\": " + jsonNumber(100.0 * m.shareOver) + "}\n";
}

std::vector<std::string> exceededLimits(const DiffReport& report, const DiffOptions& options) {
  std::vector<std::string> lines;
  auto check = [&](const char* what, double value, const std::optional<double>& limit, const char* flag) {
    if (limit && value > *limit)
      lines.push_back(std::string(what) + " " + formatted("%.6g", value) + " exceeds " + flag + " " +
                      formatted("%g", *limit));
  };
  check("RMSE", report.metrics.rmse, options.failRmse, "--fail-rmse");
  check("FLIP", report.flip, options.failFlip, "--fail-flip");
  check("percent over the threshold", 100.0 * report.metrics.shareOver, options.failPercent, "--fail-percent");
  return lines;
}

OutputPlan comparePlan(const DiffOptions& options) {
  OutputPlan plan;
  plan.reads.push_back({options.reference, "the reference image --compare reads", true});
  planHeatmap(plan, options);
  return plan;
}

void planHeatmap(OutputPlan& plan, const DiffOptions& options) {
  const std::string& path = options.heatmap;
  if (path.empty()) return;
  if (path == "-") throw UsageError("--heatmap writes a file: standard output carries the report");
  plan.writes.push_back({path, "the heat map", true, ""});
  struct stat st;
  if (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) return;  // written through
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".png") throw UsageError("cannot write '" + path + "': the heat map is a PNG file (.png)");
}

int runDiff(const DiffOptions& options) {
  OutputPlan plan;
  plan.reads.push_back({options.reference, "an image compared", true});
  plan.reads.push_back({options.test, "an image compared", true});
  planHeatmap(plan, options);
  checkPlan(plan);
  // The measures allocate and free planes of up to 32 MiB many times over. Kept in the heap they
  // are reused; mapped afresh each time (glibc's default), every page faults again, which took
  // half the time of a 1920x1080 comparison.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  const DiffReport report = compareImageFiles(options);
  if (!options.heatmap.empty()) writePngAtomic(options.heatmap, flipHeatmap(report.flipError));
  fputs((options.json ? diffJson(report) : diffTable(report)).c_str(), stdout);
  const std::vector<std::string> exceeded = exceededLimits(report, options);
  for (const std::string& line : exceeded) fprintf(stderr, "raytex: %s\n", line.c_str());
  return exceeded.empty() ? 0 : 1;
}
