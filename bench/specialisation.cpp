// Benchmark (prints numbers, asserts nothing): a pipeline specialised to the scene's
// kinds, object and light counts vs one specialised to its kinds only vs none, on one scene.
// Usage: raytex_bench_specialisation SCENE [WIDTH HEIGHT RUNS]
// Run with MESA_SHADER_CACHE_DISABLE=true so each pipeline is compiled for real.
#include "common.h"
#include "bench.h"
#include "gpu_scene.h"
#include "parser.h"
#include "renderer.h"

#include <chrono>
#include <cstdio>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  BenchArgs args;
  if (!parseBenchArgs(argc, argv, &args)) return 2;
  const uint32_t width = args.width, height = args.height;
  const int runs = args.runs;
  try {
    Scene scene = parseSceneFile(args.scene);
    GpuScene gpuScene = buildGpuScene(scene, width, height);
    // The kernel built around the scene's values (raytex render's); specialised to its kinds
    // and counts; to its texture kinds only (object and light counts read at run time); and
    // not at all (every kind compiled in).
    SceneShape kindsOnly;
    kindsOnly.sphereKinds = gpuScene.shape.sphereKinds;
    kindsOnly.planeKinds = gpuScene.shape.planeKinds;
    struct Variant {
      const char* name;
      SceneShape shape;
      BakedScene baked;
    } variants[] = {{"values", gpuScene.shape, bakeScene(gpuScene)},
                    {"scene", gpuScene.shape, {}},
                    {"kinds only", kindsOnly, {}},
                    {"none", SceneShape{}, {}}};
    printf("%s %ux%u, %d runs, medians in ms\n", args.scene.c_str(), width, height, runs);
    printf("%-12s %10s %14s %10s\n", "specialised", "create", "first frame", "frame");
    for (const Variant& v : variants) {
      std::vector<double> create, first, frame;
      for (int run = 0; run < runs; ++run) {
        Renderer r;
        createRenderer(r, {});
        uploadScene(r, gpuScene);
        Clock::time_point t = Clock::now();
        KernelKey key = kernelKey(gpuScene, KernelOptions{});
        key.shape = v.shape;
        key.baked = v.baked;
        preparePipeline(r, key);
        create.push_back(msSince(t));
        t = Clock::now();
        renderFrame(r);  // lavapipe finishes compiling at the first dispatch
        first.push_back(msSince(t));
        t = Clock::now();
        renderFrame(r);
        frame.push_back(msSince(t));
        destroyRenderer(r);
      }
      printf("%-12s %10.1f %14.1f %10.1f\n", v.name, median(create), median(first), median(frame));
    }
  } catch (const std::exception& e) {
    fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
