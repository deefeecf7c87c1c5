// `raytex render`: one scene on Vulkan or on the float64 reference, several as a batch, and
// --compare's diff of the output against a reference image.
#pragma once

#include "diff_report.h"
#include "render_options.h"

// Renders and writes the outputs; with compare.reference, then compares the output as `raytex
// diff` does. Returns 0, or 3 when a --fail-* limit of the comparison is exceeded (render's own
// failures throw an Error, error.h).
int runRenderCommand(const RenderOptions& options, const DiffOptions& compare);
