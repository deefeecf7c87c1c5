// Parser of the course's .cfg scene format (docs/scene-format.md).
// Knows nothing of Vulkan. Every error is a SceneError "file:line:col: message".
#pragma once

#include "read_policy.h"
#include "scene.h"

#include <string>

// Reads and parses a scene file; #include paths resolve relative to the including file. A
// scene with no sphere or plane is an error (FILE:1:1): it would render the background alone.
// A file is a scene when it is empty or comment-only, or its first token is #include, a
// top-level keyword or within edit distance 2 of one; any other file, named here or included,
// is refused as "not a scene file" with nothing of its content quoted. Includes and images
// must satisfy `policy` (the file named here is always read), and all files read together hold
// at most policy.maxSceneBytes, in at most kMaxIncludes includes (read_policy.h); a scene over a
// count limit stops at its first item over it (scene_limits.h, checkRoomFor).
Scene parseSceneFile(const std::string& path, const ReadPolicy& policy = ReadPolicy{});

// Parses scene text as if it were the file `fileName` (used for error locations and
// to resolve #include and image paths relative to fileName's directory).
Scene parseSceneText(const std::string& text, const std::string& fileName, const ReadPolicy& policy = ReadPolicy{});
