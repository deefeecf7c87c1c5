#include "overlay.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>

namespace {

constexpr int kTextScale = 2;

// The pixel darkened to a quarter, so text over it reads.
uint32_t darkened(uint32_t pixel) { return (pixel >> 2 & 0x003F3F3Fu) | (pixel & 0xFF000000u); }

void fillRect(OverlayPixels& image, int x0, int y0, int x1, int y1, uint32_t colour) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) image.pixels[size_t(y) * size_t(image.width) + size_t(x)] = colour;
}

void darkenRect(OverlayPixels& image, int x0, int y0, int x1, int y1) {
  for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) {
      uint32_t& p = image.pixels[size_t(y) * size_t(image.width) + size_t(x)];
      p = darkened(p);
    }
}

// stb_easy_font's quads for `text` at (x, y), scaled `scale` times.
void drawText(OverlayPixels& image, int x, int y, const std::string& text, uint32_t colour, int scale) {
  struct Vertex {
    float x, y, z;
    uint8_t colour[4];
  };
  std::vector<Vertex> vertices(text.size() * 300 / sizeof(Vertex) + 64);
  std::string copy = text;
  const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, vertices.data(),
                                        int(vertices.size() * sizeof(Vertex)));
  for (int q = 0; q < quads; ++q) {
    const Vertex& a = vertices[size_t(q) * 4];
    const Vertex& c = vertices[size_t(q) * 4 + 2];
    fillRect(image, x + int(a.x) * scale, y + int(a.y) * scale, x + int(c.x) * scale, y + int(c.y) * scale, colour);
  }
}

void frame(OverlayPixels& image, int x0, int y0, int x1, int y1, uint32_t colour) {
  fillRect(image, x0, y0, x1, y0 + 1, colour);
  fillRect(image, x0, y1 - 1, x1, y1, colour);
  fillRect(image, x0, y0, x0 + 1, y1, colour);
  fillRect(image, x1 - 1, y0, x1, y1, colour);
}

}  // namespace

uint32_t overlayPixel(const OverlayPixels& image, uint8_t r, uint8_t g, uint8_t b) {
  const uint32_t first = image.bgra ? b : r, third = image.bgra ? r : b;
  return first | uint32_t(g) << 8 | third << 16 | 0xFF000000u;
}

namespace {

int textWidth(const std::string& text) {
  std::string copy = text;
  return stb_easy_font_width(copy.data());
}

// `text` broken at spaces into lines at most `width` of stb_easy_font's pixels wide (a word
// wider than that on a line of its own).
std::vector<std::string> wrapped(const std::string& text, int width) {
  std::vector<std::string> lines{""};
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string joined = lines.back().empty() ? word : lines.back() + " " + word;
    if (!lines.back().empty() && textWidth(joined) > width) lines.push_back(word);
    else lines.back() = joined;
    start = end + 1;
  }
  return lines;
}

}  // namespace

void drawTextBox(OverlayPixels& image, const std::vector<std::string>& lines) {
  int keyWidth = 0, descriptionWidth = 0;  // in stb_easy_font's pixels
  for (const std::string& line : lines) {
    const size_t tab = line.find('\t');
    keyWidth = std::max(keyWidth, textWidth(line.substr(0, tab)));
    if (tab != std::string::npos) descriptionWidth = std::max(descriptionWidth, textWidth(line.substr(tab + 1)));
  }
  const int margin = 8, gap = 12;
  const int scale = (keyWidth + gap + descriptionWidth) * kTextScale + 2 * margin <= image.width ? kTextScale : 1;
  // Descriptions wrap where the window is narrower than they are.
  const int room = std::max((image.width - 2 * margin) / scale - keyWidth - gap, 1);
  std::vector<std::pair<std::string, std::string>> rows;  // key column, description column
  for (const std::string& line : lines) {
    const size_t tab = line.find('\t');
    const std::vector<std::string> parts = wrapped(tab == std::string::npos ? "" : line.substr(tab + 1), room);
    for (size_t i = 0; i < parts.size(); ++i) rows.emplace_back(i == 0 ? line.substr(0, tab) : "", parts[i]);
  }
  const int lineHeight = 12 * scale, boxWidth = (keyWidth + gap + std::min(descriptionWidth, room)) * scale;
  darkenRect(image, 0, 0, boxWidth + 2 * margin, int(rows.size()) * lineHeight + 2 * margin);
  const uint32_t white = overlayPixel(image, 255, 255, 255);
  for (size_t i = 0; i < rows.size(); ++i) {
    const int y = margin + int(i) * lineHeight;
    drawText(image, margin, y, rows[i].first, white, scale);
    drawText(image, margin + (keyWidth + gap) * scale, y, rows[i].second, white, scale);
  }
}

void drawMagnifier(OverlayPixels& image, int x, int y) {
  const int half = kMagnifierSource / 2, side = kMagnifierSource * kMagnifierZoom;
  std::vector<uint32_t> source(size_t(kMagnifierSource) * kMagnifierSource);
  for (int j = 0; j < kMagnifierSource; ++j)
    for (int i = 0; i < kMagnifierSource; ++i) {
      const int sx = std::clamp(x - half + i, 0, image.width - 1), sy = std::clamp(y - half + j, 0, image.height - 1);
      source[size_t(j) * kMagnifierSource + size_t(i)] = image.pixels[size_t(sy) * size_t(image.width) + size_t(sx)];
    }
  // Beside the cursor, to its lower right, or wherever the window leaves room.
  int left = x + 16, top = y + 16;
  if (left + side > image.width) left = x - 16 - side;
  if (top + side > image.height) top = y - 16 - side;
  left = std::clamp(left, 0, std::max(image.width - side, 0));
  top = std::clamp(top, 0, std::max(image.height - side, 0));
  for (int j = 0; j < kMagnifierSource; ++j)
    for (int i = 0; i < kMagnifierSource; ++i)
      fillRect(image, left + i * kMagnifierZoom, top + j * kMagnifierZoom, left + (i + 1) * kMagnifierZoom,
               top + (j + 1) * kMagnifierZoom, source[size_t(j) * kMagnifierSource + size_t(i)]);
  const uint32_t white = overlayPixel(image, 255, 255, 255), black = overlayPixel(image, 0, 0, 0);
  frame(image, left - 1, top - 1, left + side + 1, top + side + 1, black);
  frame(image, left - 2, top - 2, left + side + 2, top + side + 2, white);
  const int c = half * kMagnifierZoom;
  frame(image, left + c - 1, top + c - 1, left + c + kMagnifierZoom + 1, top + c + kMagnifierZoom + 1, white);
}

void drawUvPass(OverlayPixels& image, const float* uv) {
  auto byte = [](float v) { return uint8_t(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f)); };
  for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i) {
    const float* p = uv + 4 * i;
    image.pixels[i] = overlayPixel(image, byte(p[0]), byte(p[1]), byte(p[2]));
  }
}

void drawSplit(OverlayPixels& image, const uint32_t* right, int splitX) {
  const int from = std::clamp(splitX, 0, image.width);
  for (int y = 0; y < image.height; ++y)
    for (int x = from; x < image.width; ++x) {
      const size_t i = size_t(y) * size_t(image.width) + size_t(x);
      image.pixels[i] = right[i];
    }
  if (splitX > 0 && splitX < image.width) fillRect(image, splitX, 0, splitX + 1, image.height, overlayPixel(image, 255, 255, 255));
}
