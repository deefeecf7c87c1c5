// The viewer's kernels: which render its frames, and which it compiles ahead while it waits, so
// that a key's material switch shows on the next frame. Lavapipe compiles a pipeline at its
// first dispatch: until the kernels specialised to the scene have run, a kernel with every kind
// the scene's materials have renders instead (the image bit for bit theirs).
#pragma once

#include "gpu_scene.h"
#include "kernel_key.h"
#include "render_options.h"
#include "renderer.h"
#include "scene.h"

// The pipeline that renders `scene` (its objects' materials as switched) progressively with the
// job's settings. Every material is packed, so an object's image may be any of the packed
// scene's elements of BINDING_IMAGES.
KernelKey viewerKey(const GpuScene& packed, const Scene& scene, const RenderJob& job);

// The kernel with every kind the scene's materials have, on spheres and planes alike: it renders
// any switch of materials, the image bit for bit the specialised kernels' (specialisation_test).
KernelKey allKindsKey(const GpuScene& packed, const Scene& scene, const RenderJob& job);

// The first of the scene's specialised kernels not compiled yet; false when all are.
bool pendingKernel(const Renderer& renderer, const GpuScene& packed, const Scene& scene, const RenderJob& job,
                   KernelKey* key);

// Makes the scene's specialised kernels current, over their tiles for the camera as packed: after
// every pack, the only times the key or the tiles change. While one of them has not run yet and
// the all-kinds kernel has, that one renders instead, so that no key waits for a compile; returns
// false then (pendingKernel names what to compile).
bool prepareViewerKernels(Renderer& renderer, const GpuScene& packed, const Scene& scene, const RenderJob& job);

// A pipeline a key could need next that has not run yet: the all-kinds kernel, then the course
// materials on the spheres, then on the planes. False when all are ready.
bool nextPipelineToWarm(const Scene& scene, const Renderer& renderer, const RenderJob& job, const GpuScene& packed,
                        KernelKey* key);
