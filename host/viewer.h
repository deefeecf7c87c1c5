// raytex view: the scene in a window, rendered by the same kernel, with keys to switch the
// course materials.
#pragma once

#include "cli.h"

// Runs until the window closes. Exit code as for render: 0, 1 runtime (no display), 2 input.
// The keys are listed in cli.cpp's usage text and the README.
int runViewer(const RenderOptions& options);
