// What one render is asked to do: the options of `raytex render`, `view` and `bench` (the command
// line's table fills them, app/cli.cpp) and the settings they resolve to with the scene's render
// block. No Vulkan.
#pragma once

#include "output_plan.h"
#include "passes.h"
#include "read_policy.h"
#include "scene.h"
#include "scene_images.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

struct RenderOptions {
  std::string scene;  // the first scene given
  std::vector<std::string> scenes;  // render: every scene given, in order (several: a batch into -o DIR/)
  std::string output = "out.png";  // "-": standard output; ending in '/': a directory (batch.h)
  std::string format = "png";  // --format: the images' format in -o DIR/ (png, exr or pfm)
  uint32_t pngDepth = 8;       // --depth 8 or 16: bits per channel of a PNG output
  bool half = false;           // --half: an EXR output in half floats (position stays float)
  bool fullMetadata = false;   // --metadata full: also the scene path, device and render time
  std::vector<Pass> passes;    // --aov: passes written with the image (passes.h)
  std::optional<uint32_t> width, height;  // flags; else the scene's render block; else 640x480
  int device = -1;        // --device N; -1: best available
  std::optional<uint32_t> samplesPerPixel;  // --spp: a square N*N, stratified, box filtered
  std::optional<TextureFilter> filter;  // --filter
  std::optional<ImageFilter> imageFilter;  // --image-filter
  bool reference = false;  // --reference: the float64 CPU renderer instead of Vulkan
  bool stats = false;     // --stats: one line of phase times (view: frame times at exit)
  bool validate = false;  // --validate, or RAYTEX_VALIDATION=1: Vulkan validation layers
  uint32_t frames = 0;    // view --frames N: quit after N frames (accumulation restarting)
  uint32_t maxImageMiB = kDefaultMaxImageMiB;  // --max-image-mib N: budget of image texture bytes uploaded
  uint32_t maxSceneMiB = kDefaultMaxSceneMiB;  // --max-scene-mib N: budget of scene text read
  std::vector<std::string> allowRead;  // --allow-read DIR (repeatable): includes and images only there
  OutputPlan alongside;  // files read and written besides the render's own (render --compare), checked with them
};

// Largest accepted width or height, and pixel count (the float image and its readback
// buffer take 32 bytes per pixel).
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint64_t kMaxPixels = uint64_t(8192) * 8192;

// The settings of one render: flags, else the scene's render block, else the defaults (the
// viewer accumulates defaultSamplesPerPixel where render takes 1).
struct RenderJob {
  uint32_t width = 640, height = 480;
  uint32_t samplesPerPixel = 1, samplesPerSide = 1;
  TextureFilter filter = TextureFilter::Point;
  ImageFilter imageFilter = ImageFilter::Anisotropic;
};

// What the scene may make raytex read: --allow-read and --max-scene-mib.
ReadPolicy readPolicyOf(const RenderOptions& options);

// The filter: --filter, else the scene's render block, else point.
TextureFilter resolvedFilter(const RenderOptions& options, const RenderSettings& scene);

// Throws UsageError when the size is over kMaxPixels, or for passes or N x N samples with
// --filter coverage.
RenderJob resolveJob(const RenderOptions& options, const RenderSettings& scene, uint32_t defaultSamplesPerPixel);
