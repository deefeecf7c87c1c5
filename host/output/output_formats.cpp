#include "output_formats.h"

#include "file_extension.h"

#include "error.h"
#include "exr_writer.h"
#include "image_file.h"
#include "float_file.h"
#include "image_writer.h"
#include "pfm_writer.h"
#include "png_writer.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>

namespace {

std::unique_ptr<BandSink> pngWriter(const OutputSpec& s) {
  return makePngSink(s.path, s.width, s.height, s.pngDepth, -1, 3, s.metadata);
}
std::unique_ptr<BandSink> pfmWriter(const OutputSpec& s) { return makePfmSink(s.path, s.width, s.height, -1, 3); }

// EXR and PFM hold linear values as stored, of high dynamic range.
LinearImage exrReader(const std::string& path, uint64_t maxBytes) { return {readExr(path, maxBytes), false}; }
LinearImage pfmReader(const std::string& path, uint64_t maxBytes) { return {readPfm(path, maxBytes), false}; }

std::vector<OutputFormatInfo> makeFormats() {
  // Attribute names every EXR header defines, or that name its parts: a string attribute of the
  // same name would replace or contradict them.
  const std::vector<const char*> exrHeader = {
      "channels",           "compression", "dataWindow", "displayWindow", "lineOrder",
      "pixelAspectRatio",   "screenWindowCenter",        "screenWindowWidth", "tiles",
      "type",               "name",        "version",    "chunkCount",    "view",
      "multiView"};
  return {
      {OutputFormat::Png, "png", "a PNG output", "--depth", false, {}, pngWriter, readSrgbImage},
      {OutputFormat::Exr, "exr", "an EXR output", "--half", true, exrHeader, makeExrSink, exrReader},
      {OutputFormat::Pfm, "pfm", "a PFM output", nullptr, false, {}, pfmWriter, pfmReader},
  };
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}


}  // namespace

const std::vector<OutputFormatInfo>& outputFormats() {
  static const std::vector<OutputFormatInfo> formats = makeFormats();
  return formats;
}

const OutputFormatInfo& outputFormatInfo(OutputFormat format) {
  for (const OutputFormatInfo& info : outputFormats())
    if (info.format == format) return info;
  throw Error(ErrorKind::Internal, "no row for output format " + std::to_string(int(format)));
}

const OutputFormatInfo* findOutputFormat(const std::string& word) {
  const std::string name = lower(word);
  for (const OutputFormatInfo& info : outputFormats())
    if (name == info.name) return &info;
  return nullptr;
}

std::string outputFormatWords() {
  std::string text;
  const auto& formats = outputFormats();
  for (size_t i = 0; i < formats.size(); ++i)
    text += (i == 0 ? "" : i + 1 == formats.size() ? " or " : ", ") + std::string(formats[i].name);
  return text;
}

std::string outputExtensions() {
  std::string text;
  for (const OutputFormatInfo& info : outputFormats()) text += (text.empty() ? "." : ", .") + std::string(info.name);
  return text;
}

OutputFormat outputFormatFor(const std::string& path) {
  if (const OutputFormatInfo* info = findOutputFormat(fileExtension(path))) return info->format;
  struct stat st;
  if (path == "-" || (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)))
    return OutputFormat::Png;  // written through whatever its name
  throw UsageError("'" + path + "': unknown output format (supported: " + outputExtensions() + ")");
}

LinearImage readLinearImage(const std::string& path, uint64_t maxBytes) {
  if (const OutputFormatInfo* info = findOutputFormat(fileExtension(path))) return info->reader(path, maxBytes);
  return readSrgbImage(path, maxBytes);
}
