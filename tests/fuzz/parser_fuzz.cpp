// libFuzzer target: scene text, as if it were a file in scenes/ (so #include "texture_include.cfg"
// and the course images resolve), through the parser and, when it parses, buildGpuScene (the
// limits, material packing, image loading). Every input must either parse or throw a
// SceneError or ImageInputError with a file:line:col location; anything else (another exception, a crash, a leak, undefined
// behaviour under UBSan, a hang) is a finding. Built by RAYTEX_FUZZ=ON with clang;
// tests/fuzz/run.sh parser builds and runs it.
#include "gpu_scene.h"
#include "parser.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = std::string(RAYTEX_SOURCE_DIR) + "/scenes/fuzz.cfg";
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    Scene scene = parseSceneText(text, path);
    buildGpuScene(scene, 16, 16);
  } catch (const Error& e) {
    const std::string message = e.what();
    const bool input = e.kind == ErrorKind::Scene || e.kind == ErrorKind::ImageInput;
    if (!input || !e.located || e.loc.file.empty() || e.loc.line < 1 || e.loc.column < 1 ||
        message.rfind(e.loc.file + ":" + std::to_string(e.loc.line) + ":" + std::to_string(e.loc.column) + ": ", 0) != 0) {
      fprintf(stderr, "not a scene or image error with a file:line:col location: %s\n", message.c_str());
      abort();
    }
  }
  return 0;
}
