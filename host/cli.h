// Command-line parsing for the raytex binary. No Vulkan.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

enum class CliCommand { Help, Version, Render, View, Devices };

struct RenderOptions {
  std::string scene;
  std::string output = "out.png";
  std::optional<uint32_t> width, height;  // flags; else the scene's render block; else 640x480
  int device = -1;        // --device N; -1: best available
  std::optional<uint32_t> samplesPerPixel;  // --spp: a square N*N, stratified, box filtered
  std::optional<bool> filter;  // --filter box: textures averaged over each sample's footprint
  bool reference = false;  // --reference: the float64 CPU renderer instead of Vulkan
  bool stats = false;     // --stats: one line of phase times
  bool validate = false;  // --validate, or RAYTEX_VALIDATION=1: Vulkan validation layers
};

struct CliArgs {
  CliCommand command = CliCommand::Help;
  RenderOptions render;
};

// Largest accepted width or height, and pixel count (the float image and its readback
// buffer take 32 bytes per pixel).
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint64_t kMaxPixels = uint64_t(8192) * 8192;

// Parses argv; false with *error set (a one-line message) on bad usage.
bool parseCli(const std::vector<std::string>& args, CliArgs* out, std::string* error);

const char* usageText();
