// The `camera { }` block of a view, as the viewer's C key prints it, to paste into a scene file.
// No Vulkan.
#pragma once

#include "scene.h"

#include <string>

// The block, one key a line, every number as %.9g prints it.
std::string cameraBlock(const Camera& camera);

// `camera` with each number as the block prints it and the parser reads it back: the viewer
// keeps its orbiting camera so, so that the printed block renders exactly its view.
Camera printedCamera(const Camera& camera);
