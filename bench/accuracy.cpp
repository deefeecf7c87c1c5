// Accuracy benchmark (prints and writes numbers, asserts nothing): every method and sample
// count on a set of scenes, each timed on the GPU (timestamps, median of warm frames, with the
// kernel raytex render uses: values baked in) and
// compared with the float64 reference renderer (64x64 stratified samples per pixel).
// Writes OUTDIR/accuracy.csv and the images (sRGB PNG) that bench/accuracy_chart.py reads.
// Usage: raytex_bench_accuracy OUTDIR WIDTH HEIGHT RUNS NAME=SCENE [NAME=SCENE ...]
#include "support/reference_rmse.h"
#include "common.h"
#include "bench.h"
#include "gpu_scene.h"
#include "srgb.h"
#include "atomic_file.h"
#include "parser.h"
#include "reference_render.h"
#include "renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// One frame's GPU time: one dispatch (and the coverage filter's edge pass), or, `perSample`, the
// N x N samples one dispatch each, as raytex render renders the coverage filter's (headless.cpp).
double renderTimed(Renderer& r, bool perSample, uint32_t samples) {
  if (!perSample) {
    renderFrame(r);
    return r.lastFrameMs;
  }
  double ms = 0.0;
  for (uint32_t i = 0; i < samples; ++i) {
    renderSample(r, i);
    ms += r.lastFrameMs;
  }
  return ms;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    fprintf(stderr, "usage: %s OUTDIR WIDTH HEIGHT RUNS NAME=SCENE [NAME=SCENE ...]\n", argv[0]);
    return 2;
  }
  const std::string outDir = argv[1];
  const int width = atoi(argv[2]), height = atoi(argv[3]), runs = std::max(1, atoi(argv[4]));
  const int referenceSide = 64;  // 32x32 still differs from 64x64 by RMSE 0.0085 on the horizon
  // The filters, and for scenes with image textures the box filter with the other image methods.
  struct Method {
    const char* name;
    uint32_t filter, imageFilter;
    bool imagesOnly;
  } methods[] = {{"point", FILTER_POINT, IMAGE_FILTER_ANISOTROPIC, false},
                 {"box", FILTER_BOX, IMAGE_FILTER_ANISOTROPIC, false},
                 {"coverage", FILTER_COVERAGE, IMAGE_FILTER_ANISOTROPIC, false},
                 {"box-bilinear", FILTER_BOX, IMAGE_FILTER_BILINEAR, true},
                 {"box-trilinear", FILTER_BOX, IMAGE_FILTER_TRILINEAR, true},
                 {"box-ewa", FILTER_BOX, IMAGE_FILTER_EWA, true},
                 {"box-stochastic", FILTER_BOX, IMAGE_FILTER_STOCHASTIC, true}};
  const uint32_t sides[] = {1, 2, 4, 8};  // 1, 4, 16, 64 samples per pixel

  std::string csvPath = outDir + "/accuracy.csv";
  FILE* csv = fopen(csvPath.c_str(), "w");
  if (!csv) {
    fprintf(stderr, "cannot write %s\n", csvPath.c_str());
    return 1;
  }
  fprintf(csv, "scene,method,spp,gpu_ms,rmse,image,reference\n");
  try {
    Renderer r;
    createRenderer(r, {});
    r.coverage = true;    // room for the coverage filter's edge list
    r.accumulate = true;  // and for its sums, one sample per dispatch
    printf("device: %s; %dx%d; GPU time median of %d frames; reference %dx%d spp float64\n",
           r.device.properties.deviceName, width, height, runs, referenceSide, referenceSide);
    for (int a = 5; a < argc; ++a) {
      std::string arg = argv[a];
      size_t eq = arg.find('=');
      if (eq == std::string::npos) throw std::runtime_error("expected NAME=SCENE, got " + arg);
      std::string name = arg.substr(0, eq);
      Scene scene = parseSceneFile(arg.substr(eq + 1));

      auto t = std::chrono::steady_clock::now();
      ReferenceImage ref = renderReference(scene, width, height, referenceSide);
      double refSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      std::string refImage = name + "_reference.png";
      std::vector<float> refRgba = referenceToRgba(ref);
      writePngAtomic(outDir + "/" + refImage, encodeSrgb(refRgba.data(), width, height));
      printf("%s: reference %.1f s\n", name.c_str(), refSeconds);

      GpuScene g = buildGpuScene(scene, uint32_t(width), uint32_t(height));
      uploadScene(r, g);
      for (const Method& m : methods) {
        if (m.imagesOnly && g.shape.imageCount == 0) continue;
        for (uint32_t side : sides) {
          const bool perSample = m.filter == FILTER_COVERAGE && side > 1;
          KernelOptions kernel;
          kernel.textureFilter = m.filter;
          kernel.imageFilter = m.imageFilter;
          kernel.samplesPerSide = side;
          kernel.progressive = perSample;
          kernel.bakeValues = true;  // as raytex render builds it
          preparePipeline(r, kernelKey(g, kernel));
          renderTimed(r, perSample, side * side);  // warm-up: lavapipe compiles at the first dispatch
          std::vector<double> ms;
          for (int i = 0; i < runs; ++i) ms.push_back(renderTimed(r, perSample, side * side));
          readbackFrame(r);
          double error = rmseAgainstReference(framePixels(r), ref);
          std::string image = name + "_" + m.name + "_" + std::to_string(side * side) + ".png";
          writePngAtomic(outDir + "/" + image, encodeSrgb(framePixels(r), width, height));
          fprintf(csv, "%s,%s,%u,%.3f,%.6f,%s,%s\n", name.c_str(), m.name, side * side, median(ms),
                  error, image.c_str(), refImage.c_str());
          printf("  %-8s %3u spp  %9.2f ms  RMSE %.5f\n", m.name, side * side, median(ms), error);
        }
      }
    }
    destroyRenderer(r);
  } catch (const std::exception& e) {
    fprintf(stderr, "%s\n", e.what());
    fclose(csv);
    return 1;
  }
  fclose(csv);
  return 0;
}
