#include "texture_kinds.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace {

// --- Key constructors ---

KeyRange positive() { return {0.0, 1e300, true, false, false}; }
KeyRange wholeFrom(double lo, double hi) { return {lo, hi, false, false, true}; }

TextureKey colourKey(const char* name, MaterialSlot slot, glm::vec3 TextureDesc::*field, const char* meaning) {
  TextureKey k{name, KeyType::Colour, slot, {}, meaning};
  k.colour = field;
  return k;
}
TextureKey numberKey(const char* name, MaterialSlot slot, KeyRange range, float TextureDesc::*field,
                     const char* meaning) {
  TextureKey k{name, KeyType::Number, slot, range, meaning};
  k.number = field;
  return k;
}
TextureKey wholeKey(const char* name, MaterialSlot slot, KeyRange range, int TextureDesc::*field, const char* meaning) {
  TextureKey k{name, KeyType::Whole, slot, range, meaning};
  k.whole = field;
  return k;
}

TextureDesc defaults(TextureKind kind, glm::vec3 color1, glm::vec3 color2) {
  TextureDesc t;
  t.kind = kind;
  t.color1 = color1;
  t.color2 = color2;
  return t;
}
TextureDesc noiseDefaults(TextureKind kind, glm::vec3 color1, glm::vec3 color2, float scale, float strength,
                          int octaves) {
  TextureDesc t = defaults(kind, color1, color2);
  t.scale = scale;
  t.strength = strength;
  t.octaves = octaves;
  return t;
}

void setWrap(TextureDesc& t, size_t word) { t.wrap = word == 1 ? ImageWrap::Clamp : ImageWrap::Repeat; }
size_t wrapWord(const TextureDesc& t) { return t.wrap == ImageWrap::Clamp ? 1 : 0; }

double noPeriod(const TextureDesc&) { return 0.0; }
// The parity of floor(solid * squares) summed over the axes repeats every 2 / squares.
double solidCheckerPeriod(const TextureDesc& t) { return 2.0 / double(t.squares); }
// The noise lattice repeats every 256 (marble's sine every 2, which divides it).
double latticePeriod(const TextureDesc& t) { return 256.0 / double(t.scale); }

// --- The kinds' host rows: <fn>Row per row of shaders/kinds/kinds.h ---

// The keys, each defined once and shared by the kinds that take it.
struct Keys {
  TextureKey color1 = colourKey("color1", MaterialSlot::Color1, &TextureDesc::color1, "the colour at blend 0");
  TextureKey color2 = colourKey("color2", MaterialSlot::Color2, &TextureDesc::color2, "the colour at blend 1");
  TextureKey scale =
      numberKey("scale", MaterialSlot::ParamX, positive(), &TextureDesc::scale, "frequency multiplier of the coordinate");
  TextureKey strength =
      numberKey("strength", MaterialSlot::ParamY, KeyRange{}, &TextureDesc::strength, "amount of turbulence");
  TextureKey squares =
      numberKey("squares", MaterialSlot::ParamZ, positive(), &TextureDesc::squares, "checks per side of one tile");
  TextureKey octaves =
      wholeKey("octaves", MaterialSlot::Octaves, wholeFrom(1, 16), &TextureDesc::octaves, "noise octaves summed");
  TextureKey columns = wholeKey("columns", MaterialSlot::ParamZ, wholeFrom(1, 1024), &TextureDesc::columns,
                                "bricks per tile along u (rows: twice as many)");
  TextureKey mortar = numberKey("mortar", MaterialSlot::ParamW, KeyRange{0.0, 0.5, false, true, false},
                                &TextureDesc::mortar, "joint width, a fraction of a brick's height");
  TextureKey file{"file", KeyType::File, MaterialSlot::ImageFile, {},
                  "PNG or JPEG file, relative to the scene file that names it"};
  TextureKey wrap = wrapKey();
  std::vector<TextureKey> noise() const { return {color1, color2, scale, strength, octaves}; }

  static TextureKey wrapKey() {
    TextureKey k{"wrap", KeyType::Word, MaterialSlot::ImageWrap, {},
                 "repeat: the image tiles; clamp: once, its edge texels beyond (a decal)"};
    k.words = {"repeat", "clamp"};
    k.setWord = setWrap;
    k.word = wrapWord;
    return k;
  }
};

// What a kind's host row adds to its shared row: its keys, its defaults and its solid period.
struct HostRow {
  std::vector<TextureKey> keys;
  TextureDesc defaults;
  double (*solidPeriod)(const TextureDesc&);
};

const glm::vec3 kTurbulence1(0.95f, 0.85f, 0.6f), kTurbulence2(0.3f, 0.1f, 0.05f);

HostRow imageRow(const Keys& k, TextureKind kind) {
  return {{k.file, k.wrap}, defaults(kind, glm::vec3(1.0f), glm::vec3(0.0f)), noPeriod};
}
HostRow checkerRow(const Keys& k, TextureKind kind) {
  TextureDesc d = defaults(kind, glm::vec3(0.9f), glm::vec3(0.1f));
  d.squares = 2.0f;
  return {{k.color1, k.color2, k.squares}, d, noPeriod};
}
HostRow solidCheckerRow(const Keys& k, TextureKind kind) {
  TextureDesc d = defaults(kind, glm::vec3(0.9f, 0.1f, 0.1f), glm::vec3(0.9f));
  d.squares = 4.0f;
  return {{k.color1, k.color2, k.squares}, d, solidCheckerPeriod};
}
HostRow noiseRow(const Keys& k, TextureKind kind) {
  TextureDesc d = defaults(kind, glm::vec3(0.05f, 0.1f, 0.4f), glm::vec3(0.9f, 0.9f, 0.8f));
  d.scale = 8.0f;
  return {{k.color1, k.color2, k.scale}, d, latticePeriod};
}
HostRow marbleRow(const Keys& k, TextureKind kind) {
  return {k.noise(), noiseDefaults(kind, {0.9f, 0.88f, 0.85f}, {0.15f, 0.12f, 0.2f}, 4.0f, 6.0f, 6), latticePeriod};
}
// Wood's rings are not periodic.
HostRow woodRow(const Keys& k, TextureKind kind) {
  return {k.noise(), noiseDefaults(kind, {0.75f, 0.5f, 0.25f}, {0.35f, 0.18f, 0.07f}, 8.0f, 0.25f, 4), noPeriod};
}
HostRow turbulenceRow(const Keys& k, TextureKind kind) {
  return {k.noise(), noiseDefaults(kind, kTurbulence1, kTurbulence2, 6.0f, 1.25f, 6), latticePeriod};
}
// Derivative turbulence damps octaves on slopes, so it needs more gain for the same contrast.
HostRow dturbulenceRow(const Keys& k, TextureKind kind) {
  return {k.noise(), noiseDefaults(kind, kTurbulence1, kTurbulence2, 6.0f, 2.5f, 6), latticePeriod};
}
HostRow bricksRow(const Keys& k, TextureKind kind) {
  TextureDesc d = defaults(kind, glm::vec3(0.55f, 0.20f, 0.15f), glm::vec3(0.75f, 0.74f, 0.70f));
  d.columns = 4;
  d.mortar = 0.1f;
  return {{k.color1, k.color2, k.columns, k.mortar}, d, noPeriod};
}

TextureKindInfo kindInfo(TextureKind kind, const char* name, bool solid, bool needsNoise, double cost, HostRow row) {
  return {kind, name, solid, needsNoise, std::move(row.keys), row.defaults, row.solidPeriod, cost};
}

// The rows of shaders/kinds/kinds.h, in TEX_* order, each with its host row. Built on first use
// (textureKinds), not at static initialisation: other files' statics may read the table.
std::vector<TextureKindInfo> makeKinds() {
  const Keys keys;
#define RAYTEX_KIND_INFO(ID, NAME, Kind, fn, file, COORD, FILTER, TABLE, COST)                          \
  kindInfo(TextureKind::Kind, #file, RAYTEX_KIND_IS_UV_##COORD == 0u, RAYTEX_KIND_IS_NOISE_##TABLE == 1u, \
           COST, fn##Row(keys, TextureKind::Kind)),
  return {RAYTEX_TEXTURE_KINDS(RAYTEX_KIND_INFO)};
#undef RAYTEX_KIND_INFO
}

// "a, b or c".
std::string listWithOr(const std::vector<const char*>& items) {
  std::string text;
  for (size_t i = 0; i < items.size(); ++i)
    text += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + std::string(items[i]);
  return text;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string colourText(glm::vec3 c) {
  if (c.x == c.y && c.y == c.z) return "(" + number(c.x) + ", " + number(c.x) + ", " + number(c.x) + ")";
  return "(" + number(c.x) + ", " + number(c.y) + ", " + number(c.z) + ")";
}

std::string defaultText(const TextureKey& key, const TextureDesc& d) {
  switch (key.type) {
    case KeyType::Colour: return "`" + colourText(d.*key.colour) + "`";
    case KeyType::Number: return "`" + number(d.*key.number) + "`";
    case KeyType::Whole: return "`" + number(d.*key.whole) + "`";
    case KeyType::File: return "required";
    case KeyType::Word: return "`" + std::string(key.words[key.word(d)]) + "`";
  }
  return "";
}

const char* typeText(KeyType type) {
  switch (type) {
    case KeyType::Colour: return "colour";
    case KeyType::Number: return "number";
    case KeyType::Whole: return "number";
    case KeyType::File: return "string";
    case KeyType::Word: return "word";
  }
  return "";
}

std::string validText(const TextureKey& key) {
  if (key.type == KeyType::Colour) return "components >= 0";
  if (key.type == KeyType::File) return "not empty, at most 4096 bytes";
  if (key.type == KeyType::Word) return describeWords(key);
  return describeRange(key.range);
}

}  // namespace

const std::vector<TextureKindInfo>& textureKinds() {
  static const std::vector<TextureKindInfo> kinds = makeKinds();
  return kinds;
}

const TextureKindInfo& textureKindInfo(TextureKind kind) {
  for (const TextureKindInfo& info : textureKinds())
    if (info.kind == kind) return info;
  throw std::invalid_argument("textureKindInfo: no row for texture kind " + std::to_string(int(kind)));
}

const TextureKindInfo* findTextureKind(const std::string& name) {
  for (const TextureKindInfo& info : textureKinds())
    if (name == info.name) return &info;
  return nullptr;
}

const TextureKey* findKindKey(const TextureKindInfo& info, const std::string& name) {
  for (const TextureKey& key : info.keys)
    if (name == key.name) return &key;
  return nullptr;
}

const TextureKey* findTextureKey(const std::string& name) {
  for (const TextureKindInfo& info : textureKinds())
    if (const TextureKey* key = findKindKey(info, name)) return key;
  return nullptr;
}

TextureDesc defaultTexture(TextureKind kind) {
  return kind == TextureKind::None ? TextureDesc{} : textureKindInfo(kind).defaults;
}

bool isSolidTexture(TextureKind kind) { return kind != TextureKind::None && textureKindInfo(kind).solid; }

bool readsUv(TextureKind kind) { return kind != TextureKind::None && !textureKindInfo(kind).solid; }

const char* textureKindName(TextureKind kind) {
  for (const TextureKindInfo& info : textureKinds())
    if (info.kind == kind) return info.name;
  return "none";
}

std::string textureKindList() {
  std::vector<const char*> names;
  for (const TextureKindInfo& info : textureKinds()) names.push_back(info.name);
  return listWithOr(names);
}

std::string describeRange(const KeyRange& r) {
  if (r.whole) return "a whole number from " + number(r.lo) + " to " + number(r.hi);
  std::string lo = r.lo > -1e300 ? (r.loOpen ? "> " : ">= ") + number(r.lo) : "";
  std::string hi = r.hi < 1e300 ? (r.hiOpen ? "< " : "<= ") + number(r.hi) : "";
  if (lo.empty() && hi.empty()) return "any";
  return lo.empty() ? hi : hi.empty() ? lo : lo + " and " + hi;
}

std::string describeWords(const TextureKey& key) { return listWithOr(key.words); }

bool inRange(const KeyRange& r, double v) {
  bool aboveLo = r.loOpen ? v > r.lo : v >= r.lo;
  bool belowHi = r.hiOpen ? v < r.hi : v <= r.hi;
  return aboveLo && belowHi && (!r.whole || v == std::floor(v));
}

std::string textureKindsMarkdown() {
  std::string table = "| KIND | coordinate | key | type | default | valid | meaning |\n|---|---|---|---|---|---|---|\n";
  for (const TextureKindInfo& info : textureKinds()) {
    for (size_t i = 0; i < info.keys.size(); ++i) {
      const TextureKey& key = info.keys[i];
      std::string kind = i == 0 ? "`" + std::string(info.name) + "`" : "";
      std::string coordinate = i == 0 ? (info.solid ? "3D" : "2D") : "";
      table += "| " + kind + " | " + coordinate + " | `" + key.name + "` | " + typeText(key.type) + " | " +
               defaultText(key, info.defaults) + " | " + validText(key) + " | " + key.meaning + " |\n";
    }
  }
  return table;
}

void packTexture(const TextureDesc& texture, gpu::Material* g) {
  g->textureKind = uint32_t(texture.kind);
  g->octaves = 1;
  if (texture.kind == TextureKind::None) return;
  for (const TextureKey& key : textureKindInfo(texture.kind).keys) {
    float value = key.number ? texture.*key.number : key.whole ? float(texture.*key.whole) : 0.0f;
    switch (key.slot) {
      case MaterialSlot::Color1: g->color1 = glm::vec4(texture.*key.colour, 0.0f); break;
      case MaterialSlot::Color2: g->color2 = glm::vec4(texture.*key.colour, 0.0f); break;
      case MaterialSlot::ParamX: g->params.x = value; break;
      case MaterialSlot::ParamY: g->params.y = value; break;
      case MaterialSlot::ParamZ: g->params.z = value; break;
      case MaterialSlot::ParamW: g->params.w = value; break;
      case MaterialSlot::Octaves: g->octaves = uint32_t(texture.*key.whole); break;
      case MaterialSlot::ImageFile:  // the image's element and wrap: packed with the scene's images
      case MaterialSlot::ImageWrap: break;
    }
  }
}
