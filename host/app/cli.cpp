#include "cli.h"
#include "file_extension.h"
#include "input.h"
#include "output_formats.h"
#include "suggest.h"

#include "texture_kinds.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace {

// The commands an option applies to, as bits.
// kAll: the commands that render a scene.
enum : unsigned { kRender = 1, kView = 2, kBench = 4, kDiff = 8, kAll = kRender | kView | kBench };

uint32_t parseUint(const std::string& flag, const std::string& text, uint32_t lo, uint32_t hi) {
  char* end = nullptr;
  errno = 0;
  unsigned long long v = strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE || v < lo || v > hi)
    throw UsageError(flag + " expects an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got '" + text + "'");
  return uint32_t(v);
}

uint32_t parseSpp(const std::string& flag, const std::string& text) {
  uint32_t n = parseUint(flag, text, 1, 4096);
  uint32_t side = 1;
  while (side * side < n) ++side;
  if (side * side != n) throw UsageError(flag + " must be a square number (1, 4, 9, 16, ...), got " + text);
  return n;
}

std::string parseFormat(const std::string& flag, const std::string& text) {
  const OutputFormatInfo* format = findOutputFormat(text);
  if (!format || text != format->name) throw UsageError(flag + " expects " + outputFormatWords() + ", got '" + text + "'");
  return text;
}

uint32_t parseDepth(const std::string& flag, const std::string& text) {
  if (text != "8" && text != "16") throw UsageError(flag + " expects 8 or 16, got '" + text + "'");
  return text == "16" ? 16 : 8;
}

bool parseMetadata(const std::string& flag, const std::string& text) {
  if (text != "basic" && text != "full") throw UsageError(flag + " expects basic or full, got '" + text + "'");
  return text == "full";
}

double parseNumber(const std::string& flag, const std::string& text, double lo, double hi) {
  char* end = nullptr;
  errno = 0;
  const double v = strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v) || v < lo || v > hi) {
    char range[64];
    snprintf(range, sizeof range, "from %g to %g", lo, hi);
    throw UsageError(flag + " expects a number " + range + ", got '" + text + "'");
  }
  return v;
}

TextureFilter parseFilter(const std::string& flag, const std::string& text) {
  std::optional<TextureFilter> filter = textureFilterNamed(text);
  if (!filter) throw UsageError(flag + " expects point, box or coverage, got '" + text + "'");
  return *filter;
}

ImageFilter parseImageFilter(const std::string& flag, const std::string& text) {
  std::optional<ImageFilter> filter = imageFilterNamed(text);
  if (!filter) throw UsageError(flag + " expects anisotropic, trilinear, bilinear, ewa or stochastic, got '" + text + "'");
  return *filter;
}

std::string nonEmpty(const std::string& flag, const std::string& text, const char* what) {
  if (text.empty()) throw UsageError(flag + " needs " + what);
  return text;
}

// One row per option: parsing, --help and docs/cli.md read this table and nothing else.
struct CliOption {
  const char* name;   // "--width"
  const char* alias;  // "-o", or nullptr
  const char* value;  // the value's name in the help ("W"); nullptr: a flag without a value
  unsigned commands;  // kRender | kView | kBench
  const char* help;   // one sentence; --help wraps it
  void (*apply)(CliArgs& cli, const std::string& flag, const std::string& value);
};

const CliOption kOptions[] = {
    {"--output", "-o", "FILE", kAll,
     "the PNG to write (default out.png; bench writes one only when given), atomically; a device or FIFO "
     "is written through; - is standard output (render only); a file the command reads, or writes already, is "
     "refused before any work (docs/outputs.md, the output plan); DIR/ "
     "(render): each scene's image as DIR/<scene>.png, required with several scenes",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.output = nonEmpty(f, v, "a file name"); }},
    {"--format", nullptr, "FORMAT", kRender,
     "the format of the images written into -o DIR/: png (default), exr or pfm (a file's format comes from "
     "its extension)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.format = parseFormat(f, v); }},
    {"--depth", nullptr, "BITS", kRender, "bits per channel of a PNG output: 8 (default) or 16",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.pngDepth = parseDepth(f, v); }},
    {"--half", nullptr, nullptr, kRender, "write an EXR output in half floats (default 32-bit float; position stays float)",
     [](CliArgs& c, const std::string&, const std::string&) { c.render.half = true; }},
    {"--metadata", nullptr, "WHAT", kRender,
     "metadata in the output (PNG text chunks, EXR attributes): basic (default: raytex version, size, spp, "
     "filter; the same for every render of a view) or full (also the scene path, device and render time)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.fullMetadata = parseMetadata(f, v); }},
    {"--aov", nullptr, "PASSES", kRender,
     "passes to write with the image, comma-separated: uv, normal, depth, position, albedo, footprint, lod, "
     "octaves (the last three need --filter box): layers of an EXR, else files OUT.PASS.pfm (.png for albedo) "
     "beside it; docs/outputs.md",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.passes = parsePassList(f, v); }},
    {"--width", nullptr, "W", kAll, "image width in pixels (default: the scene's render block, else 640)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.width = parseUint(f, v, 1, kMaxImageSide); }},
    {"--height", nullptr, "H", kAll, "image height in pixels (default: the scene's render block, else 480)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.height = parseUint(f, v, 1, kMaxImageSide); }},
    {"--spp", nullptr, "N", kAll,
     "samples per pixel, a square number (1, 4, 9, ...): an N x N stratified grid, box filtered (default: the "
     "scene's render block, else 1 for render and bench, 64 for view)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.samplesPerPixel = parseSpp(f, v); }},
    {"--filter", nullptr, "MODE", kAll,
     "texture filtering: point (default: sample at the hit), box (average textures over each sample's "
     "footprint from ray differentials) or coverage (box, and where a silhouette, the horizon, a crease or a shadow's "
     "edge crosses a sample's cell, each side weighted by its share of the cell: the pixel at 1 spp)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.filter = parseFilter(f, v); }},
    {"--image-filter", nullptr, "METHOD", kAll,
     "how box and coverage filter image textures over the footprint: anisotropic (default: trilinear probes along "
     "its long axis), trilinear (one lookup at the level of the long axis), bilinear (level 0, no mip levels), ewa "
     "(elliptical Gaussian over at most 16 texels a level) or stochastic (one texel per sample, drawn from the "
     "footprint's filter)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.imageFilter = parseImageFilter(f, v); }},
    {"--reference", nullptr, nullptr, kRender,
     "render on the CPU in float64 (slow; the accuracy reference), no Vulkan; samples per pixel from --spp "
     "(default 1: docs/accuracy.md's reference is --spp 4096, 64 x 64)",
     [](CliArgs& c, const std::string&, const std::string&) { c.render.reference = true; }},
    {"--device", nullptr, "N", kAll,
     "Vulkan device index from `raytex devices` (default: the best GPU, else the CPU driver lavapipe)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.device = int(parseUint(f, v, 0, 255)); }},
    {"--frames", nullptr, "N", kView, "quit after N frames, accumulation restarting (for benchmarks)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.frames = parseUint(f, v, 1, 1000000); }},
    {"--runs", nullptr, "N", kBench, "renders to take medians over, 1 to 1000 (default 5)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.bench.runs = parseUint(f, v, 1, 1000); }},
    {"--json", nullptr, nullptr, kBench | kDiff,
     "print one JSON object instead of the table (keys: bench in docs/performance.md, diff in docs/cli.md)",
     [](CliArgs& c, const std::string&, const std::string&) { c.bench.json = c.diff.json = true; }},
    {"--stats", nullptr, nullptr, kRender | kView,
     "render: print one line of phase times in milliseconds (with --filter coverage, also the pixels its edge "
     "pass shaded again, or the samples above 1 spp); view: frame and material-switch times at exit",
     [](CliArgs& c, const std::string&, const std::string&) { c.render.stats = true; }},
    {"--validate", nullptr, nullptr, kAll, "enable Vulkan validation layers (also RAYTEX_VALIDATION=1)",
     [](CliArgs& c, const std::string&, const std::string&) { c.render.validate = true; }},
    {"--max-image-mib", nullptr, "N", kAll,
     "refuse a scene whose image textures would upload more than N MiB (default 512)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.maxImageMiB = parseUint(f, v, 1, 1048576); }},
    {"--max-scene-mib", nullptr, "N", kAll,
     "refuse a scene whose files (the scene and every file it includes, each time it is included) hold more "
     "than N MiB together (default 256)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.render.maxSceneMiB = parseUint(f, v, 1, 1048576); }},
    {"--allow-read", nullptr, "DIR", kAll,
     "read #include files and images only inside DIR (repeatable; the scene named is always read): "
     "docs/security.md",
     [](CliArgs& c, const std::string& f, const std::string& v) {
       c.render.allowRead.push_back(nonEmpty(f, v, "a directory"));
     }},
    {"--compare", nullptr, "REF", kRender,
     "after the render, compare the output file with the image REF as raytex diff does and print the report; "
     "exit 3 when a --fail-* limit is exceeded",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.diff.reference = nonEmpty(f, v, "an image file"); }},
    {"--threshold", nullptr, "T", kDiff | kRender,
     "the linear channel difference a pixel must exceed to count as differing (default 0.01: above the widest "
     "step between 8-bit sRGB codes, so rounding never counts)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.diff.threshold = parseNumber(f, v, 0.0, 1e30); }},
    {"--heatmap", nullptr, "FILE", kDiff | kRender,
     "write the FLIP error per pixel as a PNG heat map (dark purple: none, pale yellow: the most), atomically; a "
     "file the command reads or writes already is refused",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.diff.heatmap = nonEmpty(f, v, "a file name"); }},
    {"--fail-rmse", nullptr, "X", kDiff | kRender, "exit 1 (render --compare: 3) when the RMSE (linear) exceeds X",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.diff.failRmse = parseNumber(f, v, 0.0, 1e30); }},
    {"--fail-flip", nullptr, "X", kDiff | kRender, "exit 1 (render --compare: 3) when the mean FLIP error exceeds X (0 to 1)",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.diff.failFlip = parseNumber(f, v, 0.0, 1.0); }},
    {"--fail-percent", nullptr, "P", kDiff | kRender,
     "exit 1 (render --compare: 3) when more than P percent of the pixels differ by more than --threshold",
     [](CliArgs& c, const std::string& f, const std::string& v) { c.diff.failPercent = parseNumber(f, v, 0.0, 100.0); }},
};

// Options without effect when another is given: refused rather than ignored.
struct NoEffect {
  const char* when;    // an option given
  const char* option;  // an option that then does nothing
  const char* why;
};
const NoEffect kNoEffect[] = {
    {"--reference", "--filter", "the reference samples each texture at its hit point"},
    {"--reference", "--device", "the reference renders on the CPU"},
    {"--reference", "--validate", "the reference uses no Vulkan"},
};

const struct {
  CliCommand command;
  const char* name;
  unsigned bit;
  const char* operands;  // the words after the command in its synopsis
  const char* summary;
} kCommands[] = {
    {CliCommand::Render, "render", kRender, "SCENE...",
     "Ray-trace SCENE (a .cfg file) on a Vulkan device and write a PNG. Several scenes render one after "
     "another on one device into -o DIR/; a scene that fails is reported and the others still render, and "
     "the exit code is that of the first that failed."},
    {CliCommand::View, "view", kView, "SCENE",
     "Show SCENE in a window, rendered by the same kernel one sample per frame and accumulated while nothing "
     "changes, up to --spp samples. Saving the scene file reloads it; the title shows the materials, samples "
     "and ms/frame."},
    {CliCommand::Bench, "bench", kBench, "SCENE",
     "Render SCENE --runs times, each a whole render from parse to PNG, and print the median time of each "
     "phase, the GPU time per frame (timestamps, one extra frame per run), Mpixel/s and Mray/s (primary + "
     "shadow rays)."},
    {CliCommand::Diff, "diff", kDiff, "A B",
     "Compare image B with image A (PNG, JPEG, EXR or PFM, of one size): RMSE and PSNR of the linear values, SSIM "
     "of the sRGB values, the mean FLIP error, the largest channel difference and the share of pixels over "
     "--threshold, as a table or JSON. Exit 0 when within every --fail-* limit given, 1 when over one, 2 on any "
     "failure."},
};

// The view keys, from the viewer's key table (the list H shows).
std::string viewKeys() {
  std::string out = "view keys:\n";
  for (const KeyHelp& row : keyHelp()) {
    std::string keys = "  " + std::string(row.keys);
    keys.resize(std::max<size_t>(keys.size() + 2, 26), ' ');
    out += keys + row.does + "\n";
  }
  return out;
}

const char* const kExitCodes =
    "exit codes:\n"
    "  0  success\n"
    "  1  a device or Vulkan failure (an image the device cannot hold included), out of memory,\n"
    "     an output file or standard output not written, an internal error\n"
    "  2  bad input: usage, a scene, an image file refused, an output raytex may not write\n"
    "  3  render --compare: the render was written, and a --fail-* limit was exceeded\n"
    "  raytex diff, as cmp: 0 the images pass, 1 a --fail-* limit exceeded, 2 any failure\n";

const CliOption* findOption(const std::string& name) {
  for (const CliOption& o : kOptions)
    if (name == o.name || (o.alias && name == o.alias)) return &o;
  return nullptr;
}

unsigned commandBit(CliCommand command) {
  for (const auto& c : kCommands)
    if (c.command == command) return c.bit;
  return 0;
}

// "render", "render and view", "render, view and bench".
std::string commandList(unsigned bits) {
  std::vector<std::string> names;
  for (const auto& c : kCommands)
    if (bits & c.bit) names.push_back(c.name);
  std::string out;
  for (size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return out;
}

// The command word, or Help/Version/Devices that take no options.
CliCommand parseCommand(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("missing command (try raytex --help)");
  const std::string& word = args[0];
  if (word == "--help" || word == "-h" || word == "help") return CliCommand::Help;
  if (word == "--version") return CliCommand::Version;
  if (word == "devices") {
    if (args.size() > 1) throw UsageError("devices takes no arguments");
    return CliCommand::Devices;
  }
  for (const auto& c : kCommands)
    if (word == c.name) return c.command;
  throw UsageError("unknown command '" + word + "' (try raytex --help)");
}

// Splits "--name=value"; a name without '=' has no inline value.
void splitInline(const std::string& arg, std::string* name, std::optional<std::string>* value) {
  size_t eq = arg.find('=');
  if (arg.rfind("--", 0) != 0 || eq == std::string::npos) {
    *name = arg;
    return;
  }
  *name = arg.substr(0, eq);
  *value = arg.substr(eq + 1);
}

// Applies the option at args[*i] (and its value), advancing *i past what it used.
const CliOption& applyOption(const std::vector<std::string>& args, size_t* i, CliArgs* cli) {
  std::string name;
  std::optional<std::string> value;
  splitInline(args[*i], &name, &value);
  const CliOption* o = findOption(name);
  if (!o) {
    std::vector<std::string> names;
    for (const CliOption& option : kOptions) names.push_back(option.name);
    const std::string near = didYouMean(name, names);
    throw UsageError("unknown option '" + name + "'" + (near.empty() ? " (try raytex --help)" : near));
  }
  const std::string command = args[0];
  if (!(o->commands & commandBit(cli->command)))
    throw UsageError(name + " is an option of raytex " + commandList(o->commands) + ", not of " + command);
  if (!o->value && value) throw UsageError(name + " takes no value");
  if (o->value && !value) {
    if (*i + 1 >= args.size()) throw UsageError(name + " needs a value");
    value = args[++*i];
  }
  o->apply(*cli, name, value.value_or(""));
  return *o;
}

// Refuses an option that does nothing with the others given (kNoEffect, and -o - where
// standard output carries something else).
void refuseWithoutEffect(const CliArgs& cli, const std::vector<std::string>& given) {
  auto has = [&](const char* name) {
    for (const std::string& g : given)
      if (g == name) return true;
    return false;
  };
  for (const NoEffect& n : kNoEffect)
    if (has(n.when) && has(n.option))
      throw UsageError(std::string(n.option) + " has no effect with " + n.when + ": " + n.why);
  if (cli.render.output != "-") return;
  if (cli.command != CliCommand::Render)
    throw UsageError("-o - (standard output) is for raytex render; bench and view write files");
  if (cli.render.stats) throw UsageError("--stats prints to standard output, which -o - fills with the PNG");
}

// Several scenes write into a directory (-o DIR/), and --format applies only there.
void checkBatch(const CliArgs& cli, const std::vector<std::string>& given) {
  const RenderOptions& r = cli.render;
  const bool directory = !r.output.empty() && r.output.back() == '/';
  if (r.scenes.size() > 1 && !directory)
    throw UsageError("several scenes write one image each: give -o DIR/ (a directory, ending in '/')");
  if (directory && cli.command != CliCommand::Render)
    throw UsageError("-o DIR/ is for raytex render; " + std::string(cli.command == CliCommand::View ? "view" : "bench") +
                     " writes one file");
  if (directory && r.reference) throw UsageError("--reference renders one scene; -o DIR/ is for several");
  if (directory && r.stats) throw UsageError("--stats times one render; -o DIR/ renders several");
  if (!directory && std::find(given.begin(), given.end(), "--format") != given.end())
    throw UsageError("--format applies to -o DIR/; a file's format comes from its extension");
}

// The output's format as the options name it: --format for -o DIR/, PNG for standard output,
// else the file's extension in lower case ("" without one).
std::string outputFormatName(const RenderOptions& r) {
  if (!r.output.empty() && r.output.back() == '/') return r.format;
  if (r.output == "-") return "png";
  return fileExtension(r.output);
}

// render --compare: the comparison's options only with it, and an output file to compare.
void checkCompare(const CliArgs& cli, const std::vector<std::string>& given) {
  if (cli.command != CliCommand::Render) return;
  auto has = [&](const char* name) { return std::find(given.begin(), given.end(), name) != given.end(); };
  if (!has("--compare")) {
    for (const char* option : {"--threshold", "--heatmap", "--fail-rmse", "--fail-flip", "--fail-percent"})
      if (has(option)) throw UsageError(std::string(option) + " applies to raytex diff and to render with --compare");
    return;
  }
  const std::string& out = cli.render.output;
  if (out == "-" || (!out.empty() && out.back() == '/'))
    throw UsageError("--compare reads the one output file back; not with -o " + out);
}

// Options of one output format or of files on disk, refused where they would do nothing.
void checkOutputOptions(const CliArgs& cli, const std::vector<std::string>& given) {
  auto has = [&](const char* name) { return std::find(given.begin(), given.end(), name) != given.end(); };
  checkCompare(cli, given);
  const std::string format = outputFormatName(cli.render);
  for (const OutputFormatInfo& info : outputFormats())
    if (info.option && has(info.option) && format != info.name)
      throw UsageError(std::string(info.option) + " applies to " + info.output);
  if (cli.render.passes.empty()) return;
  if (cli.render.output == "-") throw UsageError("--aov writes files beside the image; -o - writes one PNG to standard output");
  if (cli.render.reference) throw UsageError("--aov comes from the Vulkan kernel; --reference writes the image only");
}

// A word that is not an option: a scene (render takes several), or diff's images A and B.
void takeOperand(const std::string& word, CliArgs* cli) {
  if (cli->command == CliCommand::Diff) {
    DiffOptions& d = cli->diff;
    if (!d.test.empty()) throw UsageError("diff compares two images, got a third ('" + word + "')");
    (d.reference.empty() ? d.reference : d.test) = word;
  } else if (cli->render.scene.empty() || cli->command == CliCommand::Render) {
    if (cli->render.scene.empty()) cli->render.scene = word;
    cli->render.scenes.push_back(word);
  } else {
    throw UsageError("more than one scene given ('" + cli->render.scene + "', '" + word +
                     "'); only render takes several");
  }
}

void requireOperands(const std::string& command, const CliArgs& cli) {
  if (cli.command == CliCommand::Diff) {
    if (cli.diff.test.empty()) throw UsageError("diff needs two images (e.g. raytex diff a.png b.png)");
  } else if (cli.render.scene.empty()) {
    throw UsageError(command + " needs a scene file (e.g. raytex " + command + " scenes/textures.cfg)");
  }
}

}  // namespace

CliArgs parseCli(const std::vector<std::string>& args) {
  CliArgs cli;
  cli.command = parseCommand(args);
  if (cli.command == CliCommand::Help || cli.command == CliCommand::Version || cli.command == CliCommand::Devices)
    return cli;
  std::vector<std::string> given;  // long names of the options given
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") return CliArgs{};
    if (!a.empty() && a[0] == '-' && a != "-") {
      given.push_back(applyOption(args, &i, &cli).name);
    } else {
      takeOperand(a, &cli);
    }
  }
  requireOperands(args[0], cli);
  refuseWithoutEffect(cli, given);
  checkBatch(cli, given);
  checkOutputOptions(cli, given);
  const bool outputGiven = std::find(given.begin(), given.end(), "--output") != given.end();
  if (cli.command == CliCommand::Bench && !outputGiven) cli.render.output.clear();
  const char* env = getenv("RAYTEX_VALIDATION");
  if (env && std::string(env) == "1" && !cli.render.reference) cli.render.validate = true;
  return cli;
}

namespace {

// `text` wrapped to lines of at most `width` characters: the first after `indent` spaces, the
// rest after `hanging`.
std::string wrapped(const std::string& text, size_t indent, size_t width, size_t hanging) {
  std::string out, line;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(start, end - start);
    if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
      out += std::string(indent, ' ') + line + "\n";
      line.clear();
      indent = hanging;
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + std::string(indent, ' ') + line + "\n";
}

std::string optionSignature(const CliOption& o) {
  std::string s = o.alias ? std::string(o.alias) + ", " + o.name : o.name;
  return o.value ? s + " " + o.value : s;
}

std::string synopsis(const char* command, const char* operands, unsigned bit) {
  std::string words = std::string("raytex ") + command + " " + operands;
  for (const CliOption& o : kOptions)
    if (o.commands & bit) {
      std::string shortest = o.alias ? o.alias : o.name;
      words += " [" + shortest + (o.value ? std::string(" ") + o.value : "") + "]";
      if (std::string(o.name) == "--allow-read") words += "...";
    }
  return words;
}

}  // namespace

std::string usageText() {
  std::string out = "usage:\n";
  for (const auto& c : kCommands) out += wrapped(synopsis(c.name, c.operands, c.bit), 2, 100, 6);
  out += "  raytex devices\n  raytex --help | --version\n\ncommands:\n";
  for (const auto& c : kCommands) out += "  " + std::string(c.name) + "\n" + wrapped(c.summary, 4, 100, 4);
  out += "  devices\n    List the Vulkan devices and their indices.\n\noptions (--name value or --name=value):\n";
  for (const CliOption& o : kOptions) {
    out += "  " + optionSignature(o) + "\n";
    out += wrapped(std::string(o.help) + " [" + commandList(o.commands) + "]", 6, 100, 6);
  }
  out += "\n" + viewKeys() + "\n" + kExitCodes;
  out += "\nRendering untrusted scenes: docs/security.md\nScene format: docs/scene-format.md; texture kinds: ";
  return out + textureKindList() + "\n";
}

std::string optionReference() {
  std::string out = "| option | value | commands | meaning |\n|---|---|---|---|\n";
  for (const CliOption& o : kOptions) {
    std::string names = o.alias ? "`" + std::string(o.alias) + "`, `" + o.name + "`" : "`" + std::string(o.name) + "`";
    out += "| " + names + " | " + (o.value ? o.value : "") + " | " + commandList(o.commands) + " | " + o.help + " |\n";
  }
  out += "\n";
  for (const NoEffect& n : kNoEffect)
    out += "- `" + std::string(n.option) + "` with `" + n.when + "` is refused (exit 2): " + n.why + ".\n";
  return out;
}
