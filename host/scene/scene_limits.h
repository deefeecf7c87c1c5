// What a scene may hold: checked on the scene model, for the GPU and the CPU reference alike,
// and the loop limit of one driver, checked once the device is known. No Vulkan.
#pragma once

#include "common.h"
#include "scene.h"

#include <cstdint>

// The largest magnitude of a coordinate or distance the scene format accepts (sphere centres and
// radii, plane distances, the camera's eye and lookat, light positions; parser.cpp). The kernel
// works in 32-bit floats relative to the camera and squares the distances between the scene's
// points, and a square overflows past sqrt(FLT_MAX), about 1.8e19. Within +-1e18 per coordinate
// two points are at most 2 sqrt(3) 1e18 = 3.5e18 apart, five times within that: objects at the
// corners of the cube render like the float64 reference at +-1e18 and +-5e18, not at +-6e18
// (tests/stability/stability_float_range_test.cpp). Points further out, a plane towards its horizon, have
// their distance to a light measured scaled down (shading.glsl).
constexpr double kMaxCoordinate = 1e18;

// Materials a scene may define (its objects may use MAX_MATERIALS of them).
constexpr size_t kMaxMaterialDefinitions = 65536;

// Throws SceneError at `loc` when a scene that holds `count` of `what` ("spheres") already, of
// which raytex renders at most `max`, would take one more: "sphere 131073 is over the limit:
// raytex renders at most 131072 spheres". The parser asks before it adds each sphere, plane,
// light and material, so that a scene over a limit stops at its first item over it, before the
// rest is parsed.
void checkRoomFor(size_t count, size_t max, const char* what, const FileLoc& loc);

// Throws SceneError (at the first object, light or use over, as checkRoomFor words it) when the
// scene has more spheres, planes or lights than MAX_SPHERES, MAX_PLANES, MAX_LIGHTS
// (shaders/common.h), or its objects use more than MAX_MATERIALS materials.
void checkSceneLimits(const Scene& scene);

// Lavapipe ends a kernel's loops after 65535 passes (its guard against endless loops): the rest
// of the kernel's work is silently dropped (64 lights and 1024 spheres lost their shadow tests).
// Its kernels count their passes against this budget and report passing it (common.h,
// SPEC_LOOP_BUDGET). Before any render, a scene whose loops test every object is checked here
// against what the kernels count (shaders/loop_budget.glsl): a sample's closest hit passes
// objects + 2 times (each loop counts a masked pass), each light's shadow ray objects + 2 and
// the loop over lights lights + 1, so (lights + 1) x (objects + 3) in all, with
// LOOP_PASSES_PER_SAMPLE + 1 reserved for the loops bounded by constants.
constexpr uint64_t kMaxLoopIterations = 65000;

// Which tree, if any, a scene of `spheres` spheres walks (SPHERE_TREE_*).
uint32_t sphereTreeFor(size_t spheres);

// The objects a sample's loops test, each ray every one: the planes, and the spheres unless a
// sphere tree bounds them (sphereTreeFor).
size_t loopTestedObjects(const Scene& scene);
// The loop passes one sample makes at most where every ray tests every object it loops over.
inline uint64_t loopIterationsPerSample(const Scene& scene) {
  return uint64_t(scene.lights.size() + 1) * uint64_t(loopTestedObjects(scene) + 3) + LOOP_PASSES_PER_SAMPLE + 1;
}

// Whether `traces` samples' loops stay within kMaxLoopIterations (on lavapipe; see checkLoopLimit).
inline bool withinLoopLimit(const Scene& scene, uint32_t traces) {
  return traces * loopIterationsPerSample(scene) <= kMaxLoopIterations;
}

// Throws SceneError (at the first light over) when `traces` samples' loops pass
// kMaxLoopIterations: 1 for a kernel's sample, 2 for the coverage filter's edge pass, which shades
// both sides of an edge in one invocation. Applies to lavapipe only; samples that together would
// pass it are dispatched one at a time (headless.cpp). A sphere tree's walks are counted while
// the kernel runs.
void checkLoopLimit(const Scene& scene, uint32_t traces = 1);

// The `traces` for checkLoopLimit of a render with or without the coverage filter.
inline uint32_t loopTraces(bool coverage) { return coverage ? 2u : 1u; }
