// Files for the tests: the source tree, whole-file reads and writes, a fresh directory under the
// system's temporary directory per test, and build/test-output for images kept for looking at.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

// The source tree (tests run with it as their working directory).
inline const std::string kSourceDir = RAYTEX_SOURCE_DIR;

// The bytes of `path`, read in binary; empty where it cannot be read.
std::string readFile(const std::filesystem::path& path);

// Writes `bytes` to `path` in binary, creating its parent directories.
void writeFile(const std::filesystem::path& path, const std::string& bytes);

// How many entries the directory `dir` holds.
size_t entryCount(const std::filesystem::path& dir);

// temp_directory_path()/raytex_NAME_PID, emptied and created anew, and removed when the test
// process exits. The process id keeps tests that share a NAME apart when ctest runs their
// processes in parallel.
std::filesystem::path freshTempDir(const std::string& name);

// RAYTEX_BINARY_DIR/test-output, created: the one place outside a temporary directory where
// tests write (images of a failure, or images to look at; never read back by a test).
std::filesystem::path testOutputDir();
