// Image output files written band by band as the rows come back from the device: PNG (8 or
// 16 bits, sRGB), EXR (linear float or half, passes as layers) and PFM (linear float), each
// with its passes, all written atomically (atomic_file.h). No Vulkan.
//
// - PNG: held whole in memory (8 bits: the bytes of encodePng(encodeSrgb(...)); 16 bits:
//   sRGB to 0..65535), written at finish(). Metadata as tEXt chunks (iTXt for a value that is
//   not ASCII, taken as UTF-8) after IHDR, in the PNG files of passes too.
// - EXR: a scanline file (ZIP, INCREASING_Y) whose rows are written as their band comes; only
//   the band and OpenEXR's line buffer are held. In half floats a finite value beyond the half
//   range is written as +-65504, the largest half, and counted (clamped()); NaN and the
//   infinities are written as they are, as in float. Channels R, G, B, A (A = 1), and per pass
//   "<name>.<letter>" for each of its channelNames plus "<name>.A", the coverage. Metadata as
//   string attributes. An output that cannot seek (a device, a FIFO, standard output) gets a
//   file encoded in memory and written through at finish(), since OpenEXR writes its table of
//   row offsets last, at the start of the file.
// - PFM: "PF" (RGB) or "Pf" (grey), little-endian, rows bottom up. A regular file gets each
//   band at its place; an output that cannot seek gets the rows bottom first (bottomUp()).
//   PFM holds no metadata.
// - Passes beside a PNG or PFM: one file each beside it, passFilePath: a PNG (8-bit sRGB) for a
//   pass whose values fit [0, 1], else a PFM ("Pf" for one channel, "PF" for two or three, the
//   missing third 0). Their coverage is not written (the values are 0 on the background).
// - The same input gives the same bytes, however it is cut into bands.
#pragma once

#include "atomic_file.h"
#include "output_formats.h"
#include "passes.h"

#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

struct BandSink;

using Metadata = std::vector<std::pair<std::string, std::string>>;

struct OutputSpec {
  std::string path;
  OutputFormat format = OutputFormat::Png;
  int width = 0;
  int height = 0;
  int pngDepth = 8;    // 8 or 16
  bool half = false;   // EXR: half floats, but for passes with fullFloat
  std::vector<Pass> passes;
  Metadata metadata;   // key, value: PNG text chunks, EXR string attributes
};

// Throws UsageError for a metadata key that a PNG keyword cannot be (1 to 79 printable ASCII
// characters, no leading, trailing or double spaces), a key given twice, a value holding a NUL,
// or, for EXR, a key naming an attribute the file's header defines ("channels").
void checkMetadata(const Metadata& metadata, OutputFormat format);

// The file a pass goes to beside a PNG or PFM main file: "<stem>.<name>.png" for a pass that
// fits [0, 1], else "<stem>.<name>.pfm", the stem being the path without its extension
// (out.png: out.normal.pfm). Empty for EXR, whose layers hold the passes.
std::string passFilePath(const OutputSpec& spec, Pass pass);

// The files of one image, opened on construction (their temporaries created), written band by
// band, made visible together by finish(). Destroyed without finish(), it removes every
// temporary it made and leaves existing files as they were. Throws UsageError for a bad spec
// (checkMetadata; pass files beside standard output), IoError for a write that fails.
class ImageWriter {
 public:
  explicit ImageWriter(const OutputSpec& spec);
  ~ImageWriter();
  ImageWriter(const ImageWriter&) = delete;
  ImageWriter& operator=(const ImageWriter&) = delete;

  // True when bands sent bottom first (the last rows first) are written without being held:
  // a PFM to an output that cannot seek. Otherwise top first suits every writer. Any order is
  // correct; a band out of a writer's order is held in memory until its turn.
  bool bottomUp() const;

  // Rows firstRow .. firstRow + rows - 1: `rgba` holds rows x width linear RGBA pixels, and
  // passes[i] rows x width vec4s of spec.passes[i]. Each row once, in any order.
  void writeBand(int firstRow, int rows, const float* rgba, const std::vector<const float*>& passes);

  // Writes what remains and puts every file in place, the pass files first and the image last;
  // when one fails, the files put in place before it are removed. Every row must have been
  // written.
  void finish();

  // Colour values of the main file written as 0 because they were not finite (PNG, with
  // encodeSrgb's rule); EXR and PFM store them as they are, and count 0.
  size_t nonFinite() const;

  // Finite values of the main file, colour and passes, written as +-65504 because they lie
  // beyond the half-float range (EXR with spec.half); 0 for every other output.
  size_t clamped() const;

  // Every file written: the main path first, then the pass files.
  std::vector<std::string> paths() const;

 private:
  void publish();

  OutputSpec spec_;
  std::vector<std::unique_ptr<BandSink>> sinks_;
  std::vector<std::string> paths_;
  std::vector<bool> rowWritten_;
};

// Writes a warning line to `to` for each kind of value the main file holds otherwise than it
// was given: "warning: N non-finite colour values (written as black)" (nonFinite()) and
// "warning: N values over the half-float range clamped to +-65504" (clamped()). Nothing when
// both counts are 0.
void printOutputWarnings(const ImageWriter& output, FILE* to);
