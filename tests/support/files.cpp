#include "support/files.h"

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The directories freshTempDir made, removed when the process that made them exits (a forked
// child that exits leaves them to its parent).
struct MadeDirs {
  pid_t owner = getpid();
  std::vector<fs::path> dirs;
  ~MadeDirs() {
    if (getpid() != owner) return;
    std::error_code ignored;
    for (const fs::path& dir : dirs) fs::remove_all(dir, ignored);
  }
};

MadeDirs& madeDirs() {
  static MadeDirs made;
  return made;
}

}  // namespace

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
  madeDirs().dirs.push_back(dir);
  return dir;
}

fs::path testOutputDir() {
  fs::path dir = fs::path(RAYTEX_BINARY_DIR) / "test-output";
  fs::create_directories(dir);
  return dir;
}

size_t entryCount(const fs::path& dir) { return size_t(std::distance(fs::directory_iterator(dir), {})); }
