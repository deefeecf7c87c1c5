// What a scene may hold: checked on the scene model, for the GPU and the CPU reference alike,
// and the loop limit of one driver, checked once the device is known. No Vulkan.
#pragma once

#include "scene.h"

#include <cstdint>

// Throws SceneError (at the first object, light or use over) when the scene has more spheres,
// planes or lights than MAX_SPHERES, MAX_PLANES, MAX_LIGHTS (shaders/common.h), or its objects
// use more than MAX_MATERIALS materials.
void checkSceneLimits(const Scene& scene);

// Lavapipe ends a loop nest after 65535 iterations (its guard against endless loops): the rest
// of the kernel's work is silently dropped (64 lights and 1024 spheres lost their shadow tests).
// A sample's loops run about (lights + 1) x (objects + 1) times.
constexpr uint64_t kMaxLoopIterations = 65000;
inline uint64_t loopIterationsPerSample(size_t lights, size_t objects) {
  return uint64_t(lights + 1) * uint64_t(objects + 1);
}

// Throws SceneError (at the first light over) when a sample's loops pass kMaxLoopIterations.
// Applies to lavapipe only; samples that together would pass it are dispatched one at a time
// (headless.cpp).
void checkLoopLimit(const Scene& scene);
