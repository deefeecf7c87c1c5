// The fixture of the device tests: one Renderer per test suite with the Khronos
// validation layer on; every test fails on a new validation error.
#pragma once

#include "common.h"
#include "gpu_scene.h"
#include "renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

class RenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = new Renderer;
    createRenderer(*renderer_, {-1, true});
  }
  static void TearDownTestSuite() {
    destroyRenderer(*renderer_);
    delete renderer_;
    renderer_ = nullptr;
  }
  void SetUp() override {
    ASSERT_TRUE(renderer_->device.validation)
        << "VK_LAYER_KHRONOS_validation missing: apt-get install vulkan-validationlayers";
    errorsBefore_ = renderer_->device.validationErrors;
  }
  void TearDown() override {
    EXPECT_EQ(renderer_->device.validationErrors, errorsBefore_) << "Vulkan validation errors";
  }

  // Renders and returns linear RGBA floats (a copy: the readback buffer is reused). The
  // kernel is specialised to the scene, or to `shape` if given; `baked`: built around the
  // scene's values as in raytex render (bakeScene), or around `bakedScene` if given.
  std::vector<float> render(const Scene& scene, uint32_t width, uint32_t height, uint32_t mode,
                            uint32_t samplesPerSide = 1, uint32_t filter = FILTER_POINT,
                            const SceneShape* shape = nullptr, bool baked = false,
                            const BakedScene* bakedScene = nullptr) {
    GpuScene gpuScene = buildGpuScene(scene, width, height);
    renderer_->coverage = filter == FILTER_COVERAGE;
    // The coverage filter's samples go one dispatch each, as in raytex render (headless.cpp).
    const bool perSample = renderer_->coverage && samplesPerSide > 1;
    renderer_->accumulate = perSample;
    uploadScene(*renderer_, gpuScene);
    KernelOptions kernel;
    kernel.outputMode = mode;
    kernel.textureFilter = filter;
    kernel.imageFilter = imageFilter_;
    kernel.samplesPerSide = samplesPerSide;
    kernel.progressive = perSample;
    kernel.bakeValues = baked;
    KernelKey key = kernelKey(gpuScene, kernel);
    if (shape) key.shape = *shape;
    if (bakedScene) key.baked = *bakedScene;
    preparePipeline(*renderer_, key);
    if (!perSample) renderFrame(*renderer_);
    for (uint32_t i = 0; perSample && i < samplesPerSide * samplesPerSide; ++i) renderSample(*renderer_, i);
    readbackFrame(*renderer_);
    renderer_->accumulate = false;
    const float* pixels = framePixels(*renderer_);
    return std::vector<float>(pixels, pixels + size_t(width) * height * 4);
  }

  static inline Renderer* renderer_ = nullptr;
  uint32_t imageFilter_ = IMAGE_FILTER_ANISOTROPIC;  // the box and coverage filters' image method
  int errorsBefore_ = 0;
};

// Non-finite values in a float image (checked before any quantisation).
inline size_t countNonFinite(const std::vector<float>& pixels) {
  size_t n = 0;
  for (float v : pixels) n += !std::isfinite(v);
  return n;
}
