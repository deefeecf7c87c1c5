#include "image_writer.h"

#include "band_sink.h"
#include "error.h"
#include "output_formats.h"
#include "pfm_writer.h"
#include "png_writer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

namespace {

// "EXR" for "exr".
std::string upper(std::string text) {
  for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// Why `key` cannot be a PNG keyword, or null.
const char* badKeyword(const std::string& key) {
  if (key.empty() || key.size() > 79) return "it must be 1 to 79 characters";
  for (char c : key)
    if (c < 32 || c > 126) return "it must be printable ASCII";
  if (key.front() == ' ' || key.back() == ' ' || key.find("  ") != std::string::npos)
    return "it must not start or end with a space or hold two in a row";
  return nullptr;
}

void checkSpec(const OutputSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0 || (spec.pngDepth != 8 && spec.pngDepth != 16))
    throw Error(ErrorKind::Internal, "'" + spec.path + "': an output of " + std::to_string(spec.width) + "x" +
                                         std::to_string(spec.height) + " at " + std::to_string(spec.pngDepth) +
                                         " bits");
  checkMetadata(spec.metadata, spec.format);
  if (spec.path == "-" && !outputFormatInfo(spec.format).passesInside && !spec.passes.empty())
    throw UsageError("passes beside standard output need files of their own: name an output file, or write EXR");
}

// The writer of one pass's file beside a PNG or PFM.
std::unique_ptr<BandSink> passSink(const OutputSpec& spec, size_t index) {
  const PassInfo& info = passInfo(spec.passes[index]);
  const std::string path = passFilePath(spec, info.pass);
  if (info.fitsUnit) return makePngSink(path, spec.width, spec.height, 8, int(index), info.channels, spec.metadata);
  return makePfmSink(path, spec.width, spec.height, int(index), info.channels);
}

}  // namespace

void checkMetadata(const Metadata& metadata, OutputFormat format) {
  const OutputFormatInfo& info = outputFormatInfo(format);
  std::set<std::string> seen;
  for (const auto& [key, value] : metadata) {
    if (const char* why = badKeyword(key)) throw UsageError("metadata key '" + key + "': " + why);
    if (!seen.insert(key).second) throw UsageError("metadata key '" + key + "' is given twice");
    if (value.find('\0') != std::string::npos) throw UsageError("metadata value of '" + key + "' holds a NUL byte");
    const auto& reserved = info.reservedKeys;
    if (std::find(reserved.begin(), reserved.end(), key) != reserved.end())
      throw UsageError("metadata key '" + key + "' names an attribute every " + upper(info.name) + " file defines");
  }
}

std::string passFilePath(const OutputSpec& spec, Pass pass) {
  if (outputFormatInfo(spec.format).passesInside) return "";
  const PassInfo& info = passInfo(pass);
  const std::string stem = std::filesystem::path(spec.path).replace_extension().string();
  return stem + "." + info.name + (info.fitsUnit ? ".png" : ".pfm");
}

ImageWriter::ImageWriter(const OutputSpec& spec) : spec_(spec) {
  checkSpec(spec);
  rowWritten_.assign(size_t(spec.height), false);
  paths_.push_back(spec.path);
  sinks_.push_back(outputFormatInfo(spec.format).writer(spec));
  if (outputFormatInfo(spec.format).passesInside) return;
  for (size_t i = 0; i < spec.passes.size(); ++i) {
    paths_.push_back(passFilePath(spec, spec.passes[i]));
    sinks_.push_back(passSink(spec, i));
  }
}

ImageWriter::~ImageWriter() = default;

bool ImageWriter::bottomUp() const {
  return std::any_of(sinks_.begin(), sinks_.end(), [](const auto& sink) { return sink->bottomUp(); });
}

void ImageWriter::writeBand(int firstRow, int rows, const float* rgba, const std::vector<const float*>& passes) {
  const bool inside = firstRow >= 0 && rows > 0 && rows <= spec_.height - firstRow;
  if (!inside || passes.size() != spec_.passes.size())
    throw Error(ErrorKind::Internal, "'" + spec_.path + "': a band of rows " + std::to_string(firstRow) + " to " +
                                         std::to_string(firstRow + rows - 1) + " with " +
                                         std::to_string(passes.size()) + " passes");
  for (int y = firstRow; y < firstRow + rows; ++y) {
    if (rowWritten_[size_t(y)])
      throw Error(ErrorKind::Internal, "'" + spec_.path + "': row " + std::to_string(y) + " written twice");
    rowWritten_[size_t(y)] = true;
  }
  const Band band{firstRow, rows, rgba, passes};
  for (auto& sink : sinks_) sink->write(band);
}

void ImageWriter::finish() {
  const auto missing = std::find(rowWritten_.begin(), rowWritten_.end(), false);
  if (missing != rowWritten_.end())
    throw Error(ErrorKind::Internal, "'" + spec_.path + "': row " +
                                         std::to_string(missing - rowWritten_.begin()) + " was never written");
  for (auto& sink : sinks_) sink->complete();
  publish();
}

void ImageWriter::publish() {
  // The passes first and the image last: a failure on the way removes the files this output put
  // in place, and an image from an earlier render stays as it was.
  size_t published = 0;
  try {
    for (size_t i = 1; i <= sinks_.size(); ++i, ++published) sinks_[i % sinks_.size()]->commit();
  } catch (...) {
    for (size_t i = 1; i <= published; ++i) sinks_[i % sinks_.size()]->withdraw();
    throw;
  }
}

size_t ImageWriter::nonFinite() const { return sinks_.front()->nonFinite(); }

size_t ImageWriter::clamped() const { return sinks_.front()->clamped(); }

std::vector<std::string> ImageWriter::paths() const { return paths_; }

void printOutputWarnings(const ImageWriter& output, FILE* to) {
  if (output.nonFinite() > 0)
    fprintf(to, "warning: %zu non-finite colour values (written as black)\n", output.nonFinite());
  if (output.clamped() > 0)
    fprintf(to, "warning: %zu values over the half-float range clamped to +-65504\n", output.clamped());
}
