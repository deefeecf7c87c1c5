#include "cli.h"

#include "texture_kinds.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace {

bool parseUint(const std::string& flag, const std::string& text, uint32_t lo, uint32_t hi,
               uint32_t* out, std::string* error) {
  char* end = nullptr;
  errno = 0;
  unsigned long long v = strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE || v < lo || v > hi) {
    *error = flag + " expects an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
             ", got '" + text + "'";
    return false;
  }
  *out = uint32_t(v);
  return true;
}

}  // namespace

std::string usageText() {
  return std::string("usage: raytex render SCENE [-o out.png] [--width W] [--height H] [--spp N]\n"
         "                    [--filter point|box] [--reference] [--device N] [--stats] [--validate]\n"
         "                    [--max-image-mib N] [--allow-read DIR]...\n"
         "       raytex view SCENE [-o shot.png] [--width W] [--height H] [--spp N] [--filter point|box]\n"
         "                  [--device N] [--frames N] [--stats] [--validate] [--max-image-mib N]\n"
         "                  [--allow-read DIR]...\n"
         "       raytex bench SCENE [--width W] [--height H] [--spp N] [--filter point|box] [--runs N]\n"
         "                   [--json] [-o out.png] [--device N] [--validate] [--max-image-mib N]\n"
         "                   [--allow-read DIR]...\n"
         "       raytex devices\n"
         "       raytex --help | --version\n"
         "\n"
         "render   Ray-trace SCENE (a .cfg file) on a Vulkan device and write a PNG.\n"
         "  -o, --output FILE  output PNG (default out.png), written atomically; a device or FIFO is\n"
         "                     written through (not atomic); the scene's own files are refused\n"
         "  --width W          image width in pixels (default: the scene's render block, else 640)\n"
         "  --height H         image height in pixels (default: the scene's render block, else 480)\n"
         "  --spp N            samples per pixel, a square number (1, 4, 9, 16, ...): an N x N\n"
         "                     stratified grid, box filtered (default 1: the pixel centre)\n"
         "  --filter MODE      texture filtering: point (default: sample at the hit) or box (average\n"
         "                     checkers over each sample's footprint from ray differentials)\n"
         "  --reference        render on the CPU in float64 (slow; the accuracy reference), no Vulkan\n"
         "  --device N         Vulkan device index from `raytex devices` (default: the best GPU,\n"
         "                     else the CPU driver lavapipe)\n"
         "  --stats            print one line of phase times in milliseconds\n"
         "  --validate         enable Vulkan validation layers (also RAYTEX_VALIDATION=1)\n"
         "  --max-image-mib N  refuse a scene whose image textures would upload more than N MiB\n"
         "                     (default 512; also view and bench)\n"
         "  --allow-read DIR   read #include files and images only inside DIR (repeatable; the scene\n"
         "                     named here is always read; also view and bench): docs/security.md\n"
         "view     Show SCENE in a window, rendered by the same kernel one sample per frame and\n"
         "         accumulated while nothing changes, up to --spp samples (default: the scene's\n"
         "         render block, else 64). Keys:\n"
         "           1-8        a course material on the sphere: aSolidChecker, aNoise, aMarble,\n"
         "                      aWood, anImage, aTurbulence, aDturbulence, aChecker\n"
         "           P          the next course material on the plane\n"
         "           arrows, WASD, left-drag   orbit the camera around its lookat point\n"
         "           +/-, PageUp/PageDown, scroll   zoom\n"
         "           R          reset the view to the scene file's camera\n"
         "           F12        write -o FILE (default out.png) once every sample is in: the PNG\n"
         "                      raytex render writes with the same view, size, --spp and --filter\n"
         "           Esc, Q     quit\n"
         "  --frames N         quit after N frames (accumulation restarts; for benchmarks)\n"
         "  --stats            print frame times and material-switch times when quitting\n"
         "  Saving the scene file reloads it; the title shows the materials, samples and ms/frame.\n"
         "bench    Render SCENE --runs times (default 5), each a whole render from parse to PNG, and\n"
         "         print the median time of each phase, the GPU time per frame (timestamps, one\n"
         "         extra frame per run), Mpixel/s and Mray/s (primary + shadow rays). Writes the PNG\n"
         "         only with -o.\n"
         "  --runs N           renders to take medians over (1 to 1000)\n"
         "  --json             print one JSON object (keys in docs/performance.md) instead of a table\n"
         "devices  List the Vulkan devices and their indices.\n"
         "\n"
         "Exit codes: 0 success, 1 runtime failure (Vulkan, output file or stdout not written, out of\n"
         "memory), 2 bad input (usage, scene, image file refused, an output that is one of the scene's\n"
         "files). Rendering untrusted scenes: docs/security.md\n"
         "Scene format: docs/scene-format.md; texture kinds: ") +
         textureKindList() + "\n";
}

bool parseCli(const std::vector<std::string>& args, CliArgs* out, std::string* error) {
  *out = CliArgs{};
  if (args.empty()) {
    *error = "missing command (try raytex --help)";
    return false;
  }
  const std::string& command = args[0];
  if (command == "--help" || command == "-h" || command == "help") {
    out->command = CliCommand::Help;
    return true;
  }
  if (command == "--version") {
    out->command = CliCommand::Version;
    return true;
  }
  if (command == "devices") {
    out->command = CliCommand::Devices;
    if (args.size() > 1) {
      *error = "devices takes no arguments";
      return false;
    }
    return true;
  }
  if (command != "render" && command != "view" && command != "bench") {
    *error = "unknown command '" + command + "' (try raytex --help)";
    return false;
  }
  out->command = command == "view"    ? CliCommand::View
                 : command == "bench" ? CliCommand::Bench
                                      : CliCommand::Render;
  bool outputGiven = false;
  RenderOptions& r = out->render;
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* v) {
      if (i + 1 >= args.size()) {
        *error = a + " needs a value";
        return false;
      }
      *v = args[++i];
      return true;
    };
    std::string v;
    if (a == "--help" || a == "-h") {
      out->command = CliCommand::Help;
      return true;
    } else if (a == "-o" || a == "--output") {
      if (!value(&r.output)) return false;
      outputGiven = true;
      if (r.output.empty()) {
        *error = a + " needs a file name";
        return false;
      }
    } else if (a == "--width") {
      uint32_t n = 0;
      if (!value(&v) || !parseUint(a, v, 1, kMaxImageSide, &n, error)) return false;
      r.width = n;
    } else if (a == "--height") {
      uint32_t n = 0;
      if (!value(&v) || !parseUint(a, v, 1, kMaxImageSide, &n, error)) return false;
      r.height = n;
    } else if (a == "--device") {
      uint32_t d = 0;
      if (!value(&v) || !parseUint(a, v, 0, 255, &d, error)) return false;
      r.device = int(d);
    } else if (a == "--spp") {
      uint32_t n = 0;
      if (!value(&v) || !parseUint(a, v, 1, 4096, &n, error)) return false;
      r.samplesPerPixel = n;
      uint32_t side = 1;
      while (side * side < n) ++side;
      if (side * side != n) {
        *error = "--spp must be a square number (1, 4, 9, 16, ...), got " + v;
        return false;
      }
    } else if (a == "--filter") {
      if (!value(&v)) return false;
      if (v != "point" && v != "box") {
        *error = "--filter expects point or box, got '" + v + "'";
        return false;
      }
      r.filter = v == "box";
    } else if (a == "--frames" && out->command == CliCommand::View) {
      if (!value(&v) || !parseUint(a, v, 1, 1000000, &r.frames, error)) return false;
    } else if (a == "--runs" && out->command == CliCommand::Bench) {
      if (!value(&v) || !parseUint(a, v, 1, 1000, &out->bench.runs, error)) return false;
    } else if (a == "--json" && out->command == CliCommand::Bench) {
      out->bench.json = true;
    } else if (a == "--reference" && out->command != CliCommand::Render) {
      *error = "--reference renders on the CPU to a file: use it with raytex render";
      return false;
    } else if (a == "--reference") {
      r.reference = true;
    } else if (a == "--max-image-mib") {
      if (!value(&v) || !parseUint(a, v, 1, 1048576, &r.maxImageMiB, error)) return false;
    } else if (a == "--allow-read") {
      if (!value(&v)) return false;
      if (v.empty()) {
        *error = a + " needs a directory";
        return false;
      }
      r.allowRead.push_back(v);
    } else if (a == "--stats") {
      r.stats = true;
    } else if (a == "--validate") {
      r.validate = true;
    } else if (!a.empty() && a[0] == '-') {
      *error = "unknown option '" + a + "' (try raytex --help)";
      return false;
    } else if (r.scene.empty()) {
      r.scene = a;
    } else {
      *error = "more than one scene given ('" + r.scene + "', '" + a + "')";
      return false;
    }
  }
  if (r.scene.empty()) {
    *error = command + " needs a scene file (e.g. raytex " + command + " scenes/textures.cfg)";
    return false;
  }
  if (out->command == CliCommand::Bench && !outputGiven) r.output.clear();
  const char* env = getenv("RAYTEX_VALIDATION");
  if (env && std::string(env) == "1") r.validate = true;
  return true;
}

bool resolveJob(const RenderOptions& options, const RenderSettings& s, uint32_t defaultSamplesPerPixel,
                RenderJob* job, std::string* error) {
  job->width = options.width.value_or(uint32_t(s.width.value_or(640)));
  job->height = options.height.value_or(uint32_t(s.height.value_or(480)));
  job->samplesPerPixel =
      options.samplesPerPixel.value_or(s.samplesPerPixel ? uint32_t(*s.samplesPerPixel) : defaultSamplesPerPixel);
  job->samplesPerSide = uint32_t(std::lround(std::sqrt(double(job->samplesPerPixel))));
  job->filterBox = options.filter.value_or(s.filterBox.value_or(false));
  if (uint64_t(job->width) * job->height > kMaxPixels) {
    *error = std::to_string(job->width) + "x" + std::to_string(job->height) + " exceeds the limit of " +
             std::to_string(kMaxPixels) + " pixels (8192x8192)";
    return false;
  }
  return true;
}
