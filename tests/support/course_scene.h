// The course scene (scenes/textures.cfg, read as it is in the repository) with chosen
// materials on its sphere and its floor, switched in the parsed Scene: the sphere's and the
// plane's material indices point at the named definitions of texture_include.cfg.
#pragma once

#include "scene.h"

#include <string>

// RAYTEX_SOURCE_DIR/scenes/textures.cfg.
const std::string& courseScenePath();

// The index in scene.materials of the material called `name`; -2 where none is (-1 stands
// for the default material).
int materialIndex(const Scene& scene, const std::string& name);

// The course scene with `sphereMaterial` on the sphere and `planeMaterial` on the floor.
// Throws std::invalid_argument for a name texture_include.cfg does not define.
Scene courseScene(const std::string& sphereMaterial, const std::string& planeMaterial = "aChecker");
