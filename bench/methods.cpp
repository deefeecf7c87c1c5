// Benchmark (prints numbers, asserts nothing): warm frame time (GPU timestamps) of the
// sampling and filtering methods on one scene, median of RUNS frames after a warm-up frame.
// Usage: raytex_bench_methods SCENE [WIDTH HEIGHT RUNS]
#include "common.h"
#include "bench.h"
#include "gpu_scene.h"
#include "parser.h"
#include "renderer.h"

#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  BenchArgs args;
  if (!parseBenchArgs(argc, argv, &args)) return 2;
  const uint32_t width = args.width, height = args.height;
  const int runs = args.runs;
  struct Method {
    const char* name;
    uint32_t samplesPerSide;
    uint32_t filter;
  } methods[] = {{"point, 1 spp", 1, FILTER_POINT},  {"point, 4 spp", 2, FILTER_POINT},
                 {"point, 16 spp", 4, FILTER_POINT}, {"box, 1 spp", 1, FILTER_BOX},
                 {"box, 4 spp", 2, FILTER_BOX}};
  try {
    Scene scene = parseSceneFile(args.scene);
    Renderer r;
    createRenderer(r, {});
    GpuScene g = buildGpuScene(scene, width, height);
    uploadScene(r, g);
    printf("%s %ux%u, median of %d warm frames\n", args.scene.c_str(), width, height, runs);
    for (const Method& m : methods) {
      KernelOptions kernel;
      kernel.textureFilter = m.filter;
      kernel.samplesPerSide = m.samplesPerSide;
      preparePipeline(r, kernelKey(g, kernel));
      renderFrame(r);  // warm-up: lavapipe compiles at the first dispatch
      std::vector<double> ms;
      for (int i = 0; i < runs; ++i) {
        renderFrame(r);
        ms.push_back(r.lastFrameMs);  // GPU timestamps where supported
      }
      printf("  %-14s %8.1f ms\n", m.name, median(ms));
    }
    destroyRenderer(r);
  } catch (const std::exception& e) {
    fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
