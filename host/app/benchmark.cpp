#include "benchmark.h"

#include "headless.h"
#include "median.h"
#include "parser.h"
#include "ray_count.h"

#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Medians {
  double device, parse, upload, pipeline, firstDispatch, frame, readback, encode, endToEnd;
};

// A JSON string literal (scene paths and device names may hold quotes or backslashes).
std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      snprintf(buf, sizeof(buf), "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// What the bench reports of its runs: medians, the render's size and its rays per second.
struct BenchResult {
  Medians m;
  RenderJob job;
  std::string deviceName;
  RayCount rays;
  double mpixels = 0, mrays = 0;
};

Medians mediansOf(const std::vector<PhaseTimes>& runs, const std::vector<double>& frames) {
  auto med = [&](double PhaseTimes::*phase) {
    std::vector<double> v;
    for (const PhaseTimes& t : runs) v.push_back(t.*phase);
    return median(v);
  };
  std::vector<double> ends;
  for (const PhaseTimes& t : runs) ends.push_back(t.endToEnd());
  return {med(&PhaseTimes::device),   med(&PhaseTimes::parse),         med(&PhaseTimes::upload),
          med(&PhaseTimes::pipeline), med(&PhaseTimes::firstDispatch), median(frames),
          med(&PhaseTimes::readback), med(&PhaseTimes::encode),        median(ends)};
}

void printJson(const RenderOptions& options, const BenchOptions& bench, const BenchResult& r) {
  const Medians& m = r.m;
  printf("{\"scene\": %s, \"device\": %s, \"width\": %u, \"height\": %u, \"spp\": %u, \"filter\": \"%s\", "
         "\"runs\": %u,\n \"median_ms\": {\"device\": %.3f, \"parse\": %.3f, \"upload\": %.3f, "
         "\"pipeline\": %.3f, \"first_dispatch\": %.3f, \"frame\": %.3f, \"readback\": %.3f, "
         "\"encode\": %.3f, \"end_to_end\": %.3f},\n \"mpixel_per_s\": %.3f, \"mray_per_s\": %.3f, "
         "\"rays_per_frame\": {\"primary\": %llu, \"shadow\": %llu}}\n",
         jsonString(options.scene).c_str(), jsonString(r.deviceName).c_str(), r.job.width, r.job.height,
         r.job.samplesPerPixel, textureFilterName(r.job.filter), bench.runs, m.device, m.parse, m.upload,
         m.pipeline, m.firstDispatch, m.frame, m.readback, m.encode, m.endToEnd, r.mpixels, r.mrays,
         static_cast<unsigned long long>(r.rays.primary), static_cast<unsigned long long>(r.rays.shadow));
}

void printTable(const RenderOptions& options, const BenchOptions& bench, const BenchResult& r) {
  const Medians& m = r.m;
  printf("%s: %ux%u, %u spp, %s filter, on %s\n", options.scene.c_str(), r.job.width, r.job.height,
         r.job.samplesPerPixel, textureFilterName(r.job.filter), r.deviceName.c_str());
  printf("medians of %u runs, ms\n", bench.runs);
  const struct {
    const char* name;
    double ms;
  } rows[] = {{"device creation", m.device},
              {"parse", m.parse},
              {"upload", m.upload},
              {"pipeline creation", m.pipeline},
              {"first dispatch (compile)", m.firstDispatch},
              {"readback", m.readback},
              {"PNG encode", m.encode},
              {"end to end", m.endToEnd},
              {"frame (GPU timestamps)", m.frame}};
  for (const auto& row : rows) printf("  %-26s %9.1f\n", row.name, row.ms);
  printf("%.1f Mpixel/s, %.1f Mray/s (%llu primary + %llu shadow rays per frame)\n", r.mpixels, r.mrays,
         static_cast<unsigned long long>(r.rays.primary), static_cast<unsigned long long>(r.rays.shadow));
}

}  // namespace

void runBench(const RenderOptions& options, const BenchOptions& bench) {
  std::vector<PhaseTimes> runs;
  std::vector<double> frames;
  HeadlessRender last;
  for (uint32_t run = 0; run < bench.runs; ++run) {
    last = HeadlessRender{};
    // One frame after the first: the first dispatch includes lavapipe's compile. The frame is
    // the steady one: with tile kernels wherever they save.
    renderHeadless(options, 1, &last, true);
    runs.push_back(last.times);
    frames.insert(frames.end(), last.frameMs.begin(), last.frameMs.end());
  }
  BenchResult r{mediansOf(runs, frames), last.job, last.deviceName, {}, 0, 0};
  r.rays = countRays(parseSceneFile(options.scene, readPolicyOf(options)), r.job.width, r.job.height,
                     r.job.samplesPerSide);
  const double frameSeconds = r.m.frame * 1e-3;
  if (frameSeconds > 0) {
    r.mpixels = double(r.job.width) * r.job.height / frameSeconds * 1e-6;
    r.mrays = double(r.rays.primary + r.rays.shadow) / frameSeconds * 1e-6;
  }
  if (bench.json)
    printJson(options, bench, r);
  else
    printTable(options, bench, r);
}
