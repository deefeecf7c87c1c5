// What a scene may make raytex read (docs/security.md): which files its #include directives and
// image textures may name (--allow-read), and how much scene text it may bring in
// (--max-scene-mib, the include limits). No Vulkan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

// Longest path a scene may name, in bytes (Linux PATH_MAX): messages that quote a path stay
// bounded, and the file system would refuse a longer one anyway.
constexpr size_t kMaxPathBytes = 4096;

// The bytes all files of one scene together may hold by default (--max-scene-mib N): the scene
// and every file it includes, each time it is included.
constexpr uint32_t kDefaultMaxSceneMiB = 256;

// The #include directives one scene may follow, counting a file included again each time, and
// how deep they may nest.
constexpr size_t kMaxIncludes = 1024;
constexpr size_t kMaxIncludeDepth = 16;

struct ReadPolicy {
  // Directory trees, relative to the working directory; empty: any readable file (the default).
  std::vector<std::string> allowRead;
  uint64_t maxSceneBytes = uint64_t(kDefaultMaxSceneMiB) << 20;
};

// True when the policy lets a scene read `path`: always without --allow-read, else when the
// path, with every symlink resolved, lies inside one of the trees (themselves resolved). A path
// that does not exist is judged by where it would be, so the answer does not reveal whether it
// exists.
bool mayRead(const ReadPolicy& policy, const std::string& path);
