#include "support/band_images.h"

#include <algorithm>

BandImage bandImage(int width, int height, const std::vector<Pass>& passes) {
  BandImage image{width, height, {}, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.rgba.insert(image.rgba.end(), {0.013f * float(x) + 0.5f * float(y) / float(height),
                                           1.7f - 0.05f * float(x + y), 0.25f * float((x * 7 + y * 3) % 11) - 0.5f,
                                           0.5f});
  for (size_t p = 0; p < passes.size(); ++p) {
    std::vector<float> plane;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float covered = (x + y) % 3 == 0 ? 0.0f : 1.0f;
        for (int c = 0; c < 3; ++c)
          plane.push_back(covered * (float(p + 1) * 0.1f + 0.01f * float(x) - 0.02f * float(y) + 0.3f * float(c)));
        plane.push_back(covered);
      }
    image.passes.push_back(std::move(plane));
  }
  return image;
}

void writeBands(ImageWriter& output, const BandImage& image, int rows, BandOrder order) {
  std::vector<int> starts;
  const int step = order == BandOrder::OneBand ? image.height : rows;
  for (int y = 0; y < image.height; y += step) starts.push_back(y);
  if (order == BandOrder::BottomFirst) std::reverse(starts.begin(), starts.end());
  if (order == BandOrder::Shuffled)  // a fixed mix: the odd bands, then the even ones
    std::stable_partition(starts.begin(), starts.end(), [&](int y) { return (y / step) % 2 == 1; });
  for (int first : starts) {
    const int n = std::min(step, image.height - first);
    const size_t at = size_t(first) * size_t(image.width) * 4;
    std::vector<const float*> passes;
    for (const std::vector<float>& plane : image.passes) passes.push_back(plane.data() + at);
    output.writeBand(first, n, image.rgba.data() + at, passes);
  }
}

OutputSpec bandSpec(const std::string& path, OutputFormat format, const BandImage& image,
                    const std::vector<Pass>& passes) {
  OutputSpec spec;
  spec.path = path;
  spec.format = format;
  spec.width = image.width;
  spec.height = image.height;
  spec.passes = passes;
  return spec;
}

size_t writeBandImage(const OutputSpec& spec, const BandImage& image, int rows, BandOrder order) {
  ImageWriter output(spec);
  writeBands(output, image, rows, order);
  output.finish();
  return output.nonFinite();
}
