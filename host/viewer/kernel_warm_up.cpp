#include "kernel_warm_up.h"

#include "kernel_plan.h"
#include "viewer_state.h"

#include <vector>

namespace {

// The kernels of the frames of `scene`.
std::vector<KernelKey> viewerKernels(const Renderer& renderer, const GpuScene& packed, const Scene& scene,
                                     const RenderJob& job) {
  return viewerFrameKernels(renderer, viewerKey(packed, scene, job));
}

// `scene` with course material `index` on every sphere (onPlane false) or every plane.
Scene withCourseMaterial(const Scene& scene, int index, bool onPlane) {
  Scene switched = scene;
  if (onPlane)
    for (Plane& p : switched.planes) p.material = index;
  else
    for (Sphere& s : switched.spheres) s.material = index;
  return switched;
}

}  // namespace

KernelKey viewerKey(const GpuScene& packed, const Scene& scene, const RenderJob& job) {
  KernelOptions options;
  options.textureFilter = kernelFilter(job.filter);
  options.imageFilter = kernelImageFilter(job.imageFilter);
  options.samplesPerSide = job.samplesPerSide;
  options.progressive = true;
  KernelKey key = kernelKey(packed, options);
  key.shape = sceneShape(scene);
  if (key.shape.imageCount > 0) key.shape.imageCount = uint32_t(packed.images.size());
  return key;
}

KernelKey allKindsKey(const GpuScene& packed, const Scene& scene, const RenderJob& job) {
  KernelKey key = viewerKey(packed, scene, job);
  uint32_t kinds = 1u << uint32_t(TextureKind::None);  // objects may keep the default material
  for (const Material& m : scene.materials) kinds |= 1u << uint32_t(m.texture.kind);
  key.shape.sphereKinds = key.shape.planeKinds = kinds;
  key.shape.imageCount = uint32_t(packed.images.size());
  return key;
}

bool pendingKernel(const Renderer& renderer, const GpuScene& packed, const Scene& scene, const RenderJob& job,
                   KernelKey* key) {
  for (const KernelKey& k : viewerKernels(renderer, packed, scene, job))
    if (!pipelineWarm(renderer, k)) {
      *key = k;
      return true;
    }
  return false;
}

bool prepareViewerKernels(Renderer& renderer, const GpuScene& packed, const Scene& scene, const RenderJob& job) {
  KernelKey pending;
  if (pendingKernel(renderer, packed, scene, job, &pending)) {
    const KernelKey all = allKindsKey(packed, scene, job);
    if (pipelineWarm(renderer, all)) {
      preparePipeline(renderer, all);
      return false;
    }
  }
  prepareViewerFrameKernels(renderer, packed, viewerKey(packed, scene, job));
  return true;
}

bool nextPipelineToWarm(const Scene& scene, const Renderer& renderer, const RenderJob& job, const GpuScene& packed,
                        KernelKey* key) {
  *key = allKindsKey(packed, scene, job);
  if (!pipelineWarm(renderer, *key)) return true;
  for (int onPlane = 0; onPlane < 2; ++onPlane)
    for (const char* name : kCourseMaterials) {
      const int index = materialIndex(scene, name);
      if (index >= 0 && pendingKernel(renderer, packed, withCourseMaterial(scene, index, onPlane), job, key)) return true;
    }
  return false;
}
