// A band of rows on its way to the output files, and the interface of each file's writer
// (png_writer.h, exr_writer.h, pfm_writer.h; image_writer.h drives them). No Vulkan.
#pragma once

#include <cstddef>
#include <vector>

// Rows firstRow .. firstRow + rows - 1 of the image, the image's width each: linear RGBA,
// 4 floats a pixel, and one vec4 a pixel for each pass of the spec, in its order (the pass's
// values in the first components, coverage in w).
struct Band {
  int firstRow = 0;
  int rows = 0;
  const float* rgba = nullptr;
  std::vector<const float*> passes;
  // The vec4s a writer reads: source -1 is the colour, i >= 0 the pass passes[i].
  const float* plane(int source) const { return source < 0 ? rgba : passes[size_t(source)]; }
};

// One output file's writer. Bands come in any order, each row once; a writer that needs
// another order holds a band that comes early until its turn.
struct BandSink {
  virtual ~BandSink() = default;
  // True when bands that come bottom first need no holding (a PFM written to a pipe).
  virtual bool bottomUp() const { return false; }
  virtual void write(const Band& band) = 0;
  // Writes what is left once every row is in; the file stays invisible until commit().
  virtual void complete() = 0;
  virtual void commit() = 0;
  // Removes the file commit() put in place (atomic_file.h, AtomicFile::withdraw).
  virtual void withdraw() = 0;
  // Colour values written as 0 because they were not finite (PNG; EXR and PFM keep them).
  virtual size_t nonFinite() const { return 0; }
  // Finite values written as +-65504 because they lie beyond the half range (EXR in half floats).
  virtual size_t clamped() const { return 0; }
};
