#include "read_policy.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace {

// Absolute, with symlinks resolved as far as the path exists and "." and ".." removed.
fs::path resolved(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return fs::path();
  if (p.filename().empty() && p.has_relative_path()) p = p.parent_path();  // "dir/" is "dir"
  return p;
}

// Component-wise, so that /a/bc is not inside /a/b.
bool isInside(const fs::path& p, const fs::path& root) {
  auto end = std::mismatch(root.begin(), root.end(), p.begin(), p.end()).first;
  return end == root.end();
}

}  // namespace

bool mayRead(const ReadPolicy& policy, const std::string& path) {
  if (policy.allowRead.empty()) return true;
  fs::path p = resolved(path);
  if (p.empty()) return false;
  for (const std::string& dir : policy.allowRead) {
    fs::path root = resolved(dir);
    if (!root.empty() && isInside(p, root)) return true;
  }
  return false;
}
