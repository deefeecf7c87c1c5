// A fresh, empty directory for one test's files, shared by the unit tests. No Vulkan.
#pragma once

#include <filesystem>
#include <string>

// temp_directory_path()/raytex_NAME, emptied and created anew.
inline std::filesystem::path freshTempDir(const std::string& name) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("raytex_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}
