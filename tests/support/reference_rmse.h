// A kernel image's error against the float64 reference image, as the image tests and
// bench/accuracy.cpp measure it.
#pragma once

#include "reference_render.h"

#include <vector>

// Root-mean-square difference of the RGB channels of linear RGBA floats (a GPU image) from
// the reference, over every pixel, or over the pixels flagged in `mask` (0 if none are).
double rmseAgainstReference(const float* rgba, const ReferenceImage& reference,
                            const std::vector<bool>* mask = nullptr);
