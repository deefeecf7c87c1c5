#include "batch.h"

#include "error.h"

#include <cerrno>

#include <sys/stat.h>
#include <unistd.h>

bool isOutputDirectory(const std::string& output) { return !output.empty() && output.back() == '/'; }

namespace {

// "scenes/marble.cfg" -> "marble"; a name without an extension as it is.
std::string sceneStem(const std::string& scene) {
  const size_t slash = scene.find_last_of('/');
  std::string name = slash == std::string::npos ? scene : scene.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

void checkDirectory(const std::string& directory) {
  struct stat st {};
  const int found = stat(directory.c_str(), &st) == 0 ? 0 : errno;
  if (found != 0 && found != ENOTDIR)
    throw UsageError("-o " + directory + ": no such directory (raytex does not create it)");
  if (found == ENOTDIR || !S_ISDIR(st.st_mode)) throw UsageError("-o " + directory + ": not a directory");
  if (access(directory.c_str(), W_OK | X_OK) != 0) throw IoError("cannot write into '" + directory + "'");
}

}  // namespace

std::vector<BatchItem> planBatch(const std::vector<std::string>& scenes, const std::string& directory,
                                 const std::string& extension) {
  checkDirectory(directory);
  std::vector<BatchItem> items;
  for (const std::string& scene : scenes) items.push_back({scene, directory + sceneStem(scene) + extension});
  return items;
}
