// The position pass (AOV_POSITION) in world coordinates. The kernel writes hits relative to the
// camera (every GPU position is: common.h, Frame); the eye is added here in double, so each
// coordinate is rounded to float once, after the sum. No Vulkan.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

// `pixels` vec4s of the position pass (passPixels(renderer, Pass::Position): xyz
// camera-relative, coverage in w) with `eye` added where w is 1; background pixels (w 0) stay
// (0, 0, 0, 0).
std::vector<float> worldPositions(const float* cameraRelative, size_t pixels, const glm::dvec3& eye);
