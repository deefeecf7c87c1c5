// Output files: how raytex writes an image without ever destroying what is there. No Vulkan.
//
// - A new or existing regular file is written into a file with no name in its directory
//   (O_TMPFILE), which commit links beside it and renames over it: the path is either the
//   complete new file or untouched, and no signal leaves anything behind. Where the file system
//   refuses O_TMPFILE, a named temporary file beside it serves (its name fits the directory's
//   name limit). An existing file keeps its mode; a new one gets 0666 & ~umask.
// - A symbolic link is followed: the rename replaces its target, and the link stays.
// - An existing non-regular file (a device such as /dev/null, a FIFO) is written through
//   directly, as other tools do; that write is not atomic. A FIFO with no reader is an error,
//   not a wait. "-" is standard output.
// - While a named temporary file exists, every signal that would end the process (SIGINT,
//   SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1, ...) removes it (every open one), then
//   ends the process with the signal's default action; while any output is open, SIGXFSZ is
//   ignored so that a file size limit becomes a write error. What the command writes and
//   whether it may is the output plan's (output_plan.h), checked before any output opens.
#pragma once

#include "error.h"
#include "png_file.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

// One output written as described above, in one or several writes: opened (the temporary
// created, or the device or FIFO opened) on construction, made visible by commit(). Destroyed
// without commit, it removes its temporary and the path keeps what it held. Every failure
// throws IoError naming the path.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  // A regular file (through its temporary): writeAt may place bytes anywhere.
  bool seekable() const { return kind_ == Kind::Unnamed || kind_ == Kind::Replace; }
  // Appends `size` bytes after what write() wrote before.
  void write(const uint8_t* data, size_t size);
  void write(const std::vector<uint8_t>& bytes) { write(bytes.data(), bytes.size()); }
  // Writes `size` bytes at `offset` (seekable outputs only), growing the file as needed.
  void writeAt(uint64_t offset, const uint8_t* data, size_t size);
  // Closes the output and, for a regular file, gives the temporary the path's name.
  void commit();
  // Removes the file commit() put in place (a set of files whose later member failed); an
  // output written through, or not yet committed, is left as it is.
  void withdraw();

 private:
  // Unnamed: an O_TMPFILE file; Replace: a named temporary; Through: a device or FIFO.
  enum class Kind { Unnamed, Replace, Through, Stdout };
  std::string path_;
  std::string target_;  // the path with its links followed
  std::string temp_;    // Replace: the temporary file
  Kind kind_ = Kind::Replace;
  int fd_ = -1;
  int slot_ = -1;  // Replace: the temporary's place among those signals remove
  bool signalsHeld_ = false;
  bool committed_ = false;
  bool published_ = false;  // commit() put the file at the path
};

// Writes `bytes` to `path` through an AtomicFile. Throws IoError naming the path.
void writeFileAtomic(const std::string& path, const std::vector<uint8_t>& bytes);

// Writes `bytes` to `path` with writeFileAtomic ("-": standard output). Throws IoError.
void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes);

// Encodes `image` as PNG (encodePng) and writes it with writeOutput.
void writePngAtomic(const std::string& path, const ImageRGBA8& image);

// The name of the temporary file for `path`: "NAME.tmp-XXXXXX" in the same directory, with
// NAME's bytes cut (at a UTF-8 boundary) so that the name has at most `nameMax` bytes.
std::string tempTemplate(const std::string& path, size_t nameMax);

// Standard output's last check, that everything printed was written: flushes `out` (stdout in
// main). Throws IoError "cannot write to standard output: ..." if any
// write to it failed.
void finishStdout(FILE* out);
