// Output files: how raytex writes a PNG without ever destroying what is there. No Vulkan.
//
// - A new or existing regular file is written whole through a temporary file beside it and a
//   rename: the path is either the complete new file or untouched. An existing file keeps its
//   mode; a new one gets 0666 & ~umask. The temporary name fits the directory's name limit.
// - A symbolic link is followed: the rename replaces its target, and the link stays.
// - An existing non-regular file (a device such as /dev/null, a FIFO) is written through
//   directly, as other tools do; that write is not atomic. A FIFO with no reader is an error,
//   not a wait.
// - SIGINT, SIGTERM and SIGHUP during the write remove the temporary file, then end the process
//   with the signal's default action; SIGXFSZ is ignored so that a file size limit becomes a
//   write error.
#pragma once

#include "image_io.h"
#include "scene.h"

#include <cstdint>
#include <string>
#include <vector>

// Writes `bytes` to `path` as described above. Throws IoError naming the path.
void writeFileAtomic(const std::string& path, const std::vector<uint8_t>& bytes);

// Writes `bytes` to `path` with writeFileAtomic, or to standard output when `path` is "-".
// Throws IoError.
void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes);

// Encodes `image` as PNG (encodePng) and writes it with writeOutput.
void writePngAtomic(const std::string& path, const ImageRGBA8& image);

// The name of the temporary file for `path`: "NAME.tmp-XXXXXX" in the same directory, with
// NAME's bytes cut (at a UTF-8 boundary) so that the name has at most `nameMax` bytes.
std::string tempTemplate(const std::string& path, size_t nameMax);

// Empty when writing `output` cannot overwrite the scene's own inputs; else the one-line reason
// ("refusing to write 'x.cfg': it is the scene file"). Compares device and inode with the scene
// file, every included file and every image the scene's materials name.
std::string outputClash(const std::string& output, const Scene& scene);

// Throws UsageError when raytex may not write `output` for this scene: one of its files
// (outputClash), or a regular file whose name does not end in .png. Devices, FIFOs, "-"
// (standard output) and "" (no output) pass.
void checkOutput(const std::string& output, const Scene& scene);
