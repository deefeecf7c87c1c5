// The rays one frame of the kernel traces, counted on the CPU: `raytex bench`'s Mray/s.
// No Vulkan: its tests need no device.
#pragma once

#include "scene.h"

#include <cstdint>

struct RayCount {
  uint64_t primary = 0;
  uint64_t shadow = 0;
};

// width x height x samplesPerSide^2 primary rays, through the kernel's stratified sample
// positions (the centres of a pixel's samplesPerSide^2 sub-cells), and one shadow ray per
// primary hit and light in front of the surface, as shade() casts them (shading.glsl). Hits
// are found in float64 (reference.h), so a sample grazing a silhouette may count otherwise
// than in the float32 kernel. Rows are shared between the processor's threads
// (forEachRowInParallel).
RayCount countRays(const Scene& scene, uint32_t width, uint32_t height, uint32_t samplesPerSide);
