#include "render_options.h"

#include "error.h"

#include <cmath>
#include <string>

ReadPolicy readPolicyOf(const RenderOptions& options) {
  return ReadPolicy{options.allowRead, uint64_t(options.maxSceneMiB) << 20};
}

TextureFilter resolvedFilter(const RenderOptions& options, const RenderSettings& s) {
  return options.filter.value_or(s.filter.value_or(TextureFilter::Point));
}

RenderJob resolveJob(const RenderOptions& options, const RenderSettings& s, uint32_t defaultSamplesPerPixel) {
  RenderJob job;
  job.width = options.width.value_or(uint32_t(s.width.value_or(640)));
  job.height = options.height.value_or(uint32_t(s.height.value_or(480)));
  job.samplesPerPixel =
      options.samplesPerPixel.value_or(s.samplesPerPixel ? uint32_t(*s.samplesPerPixel) : defaultSamplesPerPixel);
  job.samplesPerSide = uint32_t(std::lround(std::sqrt(double(job.samplesPerPixel))));
  job.filter = resolvedFilter(options, s);
  job.imageFilter = options.imageFilter.value_or(s.imageFilter.value_or(ImageFilter::Anisotropic));
  if (job.filter == TextureFilter::Point && job.imageFilter != ImageFilter::Anisotropic)
    throw UsageError("image filter " + std::string(imageFilterName(job.imageFilter)) +
                     " filters over the footprint: add --filter box or coverage (point looks images up at the hit)");
  for (Pass p : options.passes)
    if (passInfo(p).boxFilterOnly && job.filter == TextureFilter::Point)
      throw UsageError("--aov " + std::string(passInfo(p).name) + " comes from the box filter: add --filter box");
  if (uint64_t(job.width) * job.height > kMaxPixels)
    throw UsageError(std::to_string(job.width) + "x" + std::to_string(job.height) + " exceeds the limit of " +
                     std::to_string(kMaxPixels) + " pixels (8192x8192)");
  return job;
}
