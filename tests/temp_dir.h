// A fresh, empty directory for one test's files, shared by the unit tests. No Vulkan.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

// temp_directory_path()/raytex_NAME_PID, emptied and created anew. The process id keeps
// tests that share a NAME apart when ctest runs them in parallel (each test is a process).
inline std::filesystem::path freshTempDir(const std::string& name) {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("raytex_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}
