// The image file formats raytex writes, one row each: the format's word (--format, the file
// name's extension), its own option, where its passes go, the metadata keys it defines itself,
// its writer and its reader. The file name's format, --format and its checks, the writers of
// image_writer.h and the readers of `raytex diff` and `render --compare` all read these rows.
// Adding a format: its OutputFormat value, its row, its writer (a BandSink: band_sink.h) and
// its reader. No Vulkan.
#pragma once

#include "image_file.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct BandSink;
struct OutputSpec;

// The format an output file is written in.
enum class OutputFormat { Png, Exr, Pfm };

struct OutputFormatInfo {
  OutputFormat format;
  const char* name;          // "png": --format's word; the extension is "." + name, in any case
  const char* output;        // "a PNG output", for messages
  const char* option;        // the option that applies to this format only ("--depth"), or nullptr
  bool passesInside;         // passes as layers of the file (else files beside it: passFilePath)
  std::vector<const char*> reservedKeys;  // metadata keys the format's header defines itself
  std::unique_ptr<BandSink> (*writer)(const OutputSpec& spec);  // the image's file (not its passes')
  LinearImage (*reader)(const std::string& path, uint64_t maxBytes);  // throws ImageInputError
};

// Every format, in OutputFormat order.
const std::vector<OutputFormatInfo>& outputFormats();

const OutputFormatInfo& outputFormatInfo(OutputFormat format);

// The row whose name is `word` (any case; "png", not ".png"), or nullptr.
const OutputFormatInfo* findOutputFormat(const std::string& word);

// "png, exr or pfm" (separator ", " and last " or ") or ".png, .exr, .pfm" (dots, ", " only).
std::string outputFormatWords();
std::string outputExtensions();

// The format `path`'s extension names: .png, .exr or .pfm, any case. Standard output ("-") and
// existing devices and FIFOs are PNG unless their name ends in one of these. Throws UsageError
// for any other path ("'x.jpg': unknown output format (supported: .png, .exr, .pfm)").
OutputFormat outputFormatFor(const std::string& path);

// An image file read as linear RGB, by the reader of the format its extension names; any other
// name (.jpg, .jpeg, none) goes to the PNG and JPEG reader, which names what it refuses (a JPEG
// is read, not written). Throws ImageInputError naming the path.
LinearImage readLinearImage(const std::string& path, uint64_t maxBytes);
