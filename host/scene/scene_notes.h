// Notes on a scene that parses but may not render what its author meant: printed on stderr
// before the render, which goes on (exit 0). No Vulkan.
#pragma once

#include "scene.h"

#include <cstdio>
#include <string>
#include <vector>

// Each note as one line "file:line:col: note: ...". Today one kind: objects left in the default
// material (plain grey) while the scene defines textured materials, at the first such object.
std::vector<std::string> sceneNotes(const Scene& scene);

// sceneNotes(scene), one line each, on `out` (stderr in the commands).
void printSceneNotes(const Scene& scene, FILE* out);
