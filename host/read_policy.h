// Read confinement for scenes from untrusted sources (--allow-read, docs/security.md): which
// files a scene's #include directives and image textures may make raytex read. No Vulkan.
#pragma once

#include <string>
#include <vector>

// Longest path a scene may name, in bytes (Linux PATH_MAX): messages that quote a path stay
// bounded, and the file system would refuse a longer one anyway.
constexpr size_t kMaxPathBytes = 4096;

struct ReadPolicy {
  // Directory trees, relative to the working directory; empty: any readable file (the default).
  std::vector<std::string> allowRead;
};

// True when the policy lets a scene read `path`: always without --allow-read, else when the
// path, with every symlink resolved, lies inside one of the trees (themselves resolved). A path
// that does not exist is judged by where it would be, so the answer does not reveal whether it
// exists.
bool mayRead(const ReadPolicy& policy, const std::string& path);
