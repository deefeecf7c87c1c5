// raytex view: the scene in a window, rendered by the same kernel, with keys to switch the
// course materials.
#pragma once

#include "render_options.h"

// Runs until the window closes. Throws an Error (error.h): VulkanError with no display. The
// keys are listed in cli.cpp's usage text and the README.
void runViewer(const RenderOptions& options);
