// What the viewer draws over its image on the CPU, into the pixels it copies to the window:
// the help (H), the magnifier (Z) and the uv pass (U). Never in F12's file, which comes from
// the render's floats. Text is stb_easy_font's. No Vulkan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

// Window pixels: 8-bit R, G, B, A in the swapchain's byte order (B, G, R, A when bgra).
struct OverlayPixels {
  uint32_t* pixels = nullptr;
  int width = 0, height = 0;
  bool bgra = false;
};

// One pixel of the window's byte order from 8-bit r, g, b.
uint32_t overlayPixel(const OverlayPixels& image, uint8_t r, uint8_t g, uint8_t b);

// `lines` in a darkened box at the top-left corner, text twice stb_easy_font's size where the
// box fits the window at that size (else its own size). A tab in a line starts a second column.
void drawTextBox(OverlayPixels& image, const std::vector<std::string>& lines);

// The kMagnifierSource x kMagnifierSource pixels around (x, y) enlarged kMagnifierZoom times in
// a framed square beside the cursor (inside the window), the centre pixel outlined.
constexpr int kMagnifierZoom = 8;
constexpr int kMagnifierSource = 17;
void drawMagnifier(OverlayPixels& image, int x, int y);

// The uv pass as colours: red u, green v, blue the third coordinate of solid kinds, each
// clamped to [0, 1]; the background black. `uv` holds a vec4 per pixel (AOV_UV; w the coverage).
void drawUvPass(OverlayPixels& image, const float* uv);

// The split screen: `right` (the image's size, the same byte order) from column splitX on, and a
// white line at splitX when it lies inside the image.
void drawSplit(OverlayPixels& image, const uint32_t* right, int splitX);
