#include "support/files.h"

#include <unistd.h>

#include <fstream>
#include <iterator>

namespace fs = std::filesystem;


std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeFile(const fs::path& path, const std::string& bytes) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

fs::path freshTempDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("raytex_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path testOutputDir() {
  fs::path dir = fs::path(RAYTEX_BINARY_DIR) / "test-output";
  fs::create_directories(dir);
  return dir;
}
