// Renders FRAMES frames of SCENE after a first one (which compiles the kernel), and nothing
// else: bench/instructions.sh runs it under callgrind twice and takes the difference, the
// instructions the kernel executes per frame. Unlike times, the count does not move with the
// load of a shared machine, so kernel variants can be compared exactly.
// The kernel is built around the scene's values as in raytex render (bakeScene), unless the
// sixth argument is "unbaked"; its textures are point-sampled unless the seventh is "box"; the
// eighth, "progressive", renders as the viewer does: one sample per frame, accumulated; the ninth,
// "one", renders with the scene's one kernel, not tile kernels (host/gpu/tile_kernels.h).
// Usage: raytex_bench_frames SCENE WIDTH HEIGHT FRAMES [SAMPLES_PER_SIDE [baked|unbaked [point|box
//        [single|progressive [tiles|one]]]]]
#include "gpu_scene.h"
#include "kernel_plan.h"
#include "parser.h"
#include "renderer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc < 5) {
    fprintf(stderr,
            "usage: %s SCENE WIDTH HEIGHT FRAMES [SAMPLES_PER_SIDE [baked|unbaked [point|box "
            "[single|progressive [tiles|one]]]]]\n",
            argv[0]);
    return 2;
  }
  uint32_t width = uint32_t(atoi(argv[2])), height = uint32_t(atoi(argv[3]));
  int frames = atoi(argv[4]);
  uint32_t side = argc > 5 ? uint32_t(atoi(argv[5])) : 1;
  bool baked = !(argc > 6 && std::string(argv[6]) == "unbaked");
  uint32_t filter = argc > 7 && std::string(argv[7]) == "box" ? FILTER_BOX : FILTER_POINT;
  bool progressive = argc > 8 && std::string(argv[8]) == "progressive";
  bool tiles = !(argc > 9 && std::string(argv[9]) == "one");
  Renderer r;
  try {
    GpuScene scene = buildGpuScene(parseSceneFile(argv[1]), width, height);
    createRenderer(r, {});
    r.accumulate = progressive;
    uploadScene(r, scene);
    KernelOptions kernel;
    kernel.textureFilter = filter;
    kernel.samplesPerSide = side;
    kernel.bakeValues = baked;
    kernel.progressive = progressive;
    const KernelKey key = kernelKey(scene, kernel);
    if (tiles)  // the kernel plan's kernels for the steady frame, as raytex bench
      prepareFrameKernels(r, scene, key, INFINITY);
    else
      preparePipeline(r, key);
    renderSample(r, 0);
    for (int i = 0; i < frames; ++i) renderSample(r, progressive ? uint32_t(i + 1) % (side * side) : 0);
  } catch (const std::exception& e) {
    fprintf(stderr, "%s\n", e.what());
    destroyRenderer(r);
    return 1;
  }
  destroyRenderer(r);
  return 0;
}
