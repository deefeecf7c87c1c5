// Recursive-descent parser of the .cfg scene format (docs/scene-format.md), pbrt style:
// cfg::Tokenizer (tokenizer.h) puts a FileLoc on every token; Parser reads blocks into a Scene.
// Every error is a SceneError "file:line:col: message"; nothing else is thrown.
#include "parser.h"
#include "suggest.h"

#include "input_file.h"
#include "read_policy.h"
#include "scene_limits.h"
#include "texture_kinds.h"
#include "tokenizer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <utility>

namespace fs = std::filesystem;
using cfg::Tok;
using cfg::Token;
using cfg::describe;
using cfg::isNonFiniteWord;
using cfg::quote;

namespace {

[[noreturn]] void fail(const FileLoc& loc, const std::string& message) { throw SceneError(loc, message); }

std::string locString(const FileLoc& loc) {
  return loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

// Identity of a file for cycle detection.
std::string canonicalKey(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(path, ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  return p.string();
}

struct OpenFile {
  std::string key;   // canonical path
  std::string name;  // as shown in messages
};

struct State {
  ReadPolicy policy;
  uint64_t bytesRead = 0;  // by every file of the scene, against policy.maxSceneBytes
  size_t includes = 0;     // #include directives followed
  Scene scene;
  std::map<std::string, int> materialIndex;
  std::vector<OpenFile> includeStack;
  FileLoc cameraLoc, renderLoc, backgroundLoc, ambientLoc;  // line 0: not given yet
};

void parseText(State& st, const std::string& text, const std::string& file);

const char* const kTopLevelKeywords[] = {"sphere", "plane",  "material",   "camera",
                                         "light",  "render", "background", "ambient_light"};

// The top-level keyword within edit distance 2 of word (the closest), or nullptr.
const char* nearKeyword(const std::string& word) {
  const char* best = nullptr;
  size_t bestDistance = 3;
  for (const char* k : kTopLevelKeywords) {
    size_t d = editDistanceUpTo2(word, k);
    if (d < bestDistance) best = k, bestDistance = d;
  }
  return best;
}

// The keys of a sphere or plane block (`where`), for "did you mean".
std::vector<std::string> objectKeys(const std::string& where) {
  std::vector<std::string> keys = {"material", "tex_scale", "tex_rotate", "tex_offset"};
  if (where == "sphere") keys.insert(keys.end(), {"center", "radius"});
  else keys.insert(keys.end(), {"normal", "distance"});
  return keys;
}

const std::vector<std::string> kMaterialKeys = {"ambient", "diffuse", "specular", "shininess", "texture"};

// The texture keys that apply to `info`'s kind.
std::vector<std::string> kindKeys(const TextureKindInfo& info) {
  std::vector<std::string> keys;
  for (const TextureKey& k : info.keys) keys.push_back(k.name);
  return keys;
}

std::vector<std::string> kindNames() {
  std::vector<std::string> names;
  for (const TextureKindInfo& k : textureKinds()) names.push_back(k.name);
  return names;
}

// A file is a scene when it has no token at all, or its first token is #include, a top-level
// keyword or a near miss of one. Anything else (a token file, a system file, binary data) is
// refused without quoting any of it.
bool isSceneText(const std::string& text, const std::string& file) {
  try {
    cfg::Tokenizer tokens(text, file);
    Token first = tokens.next();
    return first.kind == Tok::End || first.kind == Tok::Include ||
           (first.kind == Tok::Ident && nearKeyword(first.text) != nullptr);
  } catch (const SceneError&) {
    return false;  // the first token does not lex
  }
}

// A path named by the string token `name` (an #include or an image): bounded in length, and
// readable under the policy. Checked before the file is opened, so a refusal says nothing of
// whether it exists.
void checkReadable(const State& st, const Token& name, const std::string& path) {
  if (path.size() > kMaxPathBytes)
    fail(name.loc, "file path is longer than " + std::to_string(kMaxPathBytes) + " bytes");
  if (!mayRead(st.policy, path)) fail(name.loc, "'" + path + "' is outside the directories --allow-read allows");
}

// For an #include that names no file: where includes are looked for, and for the course's
// materials file, where its copy is.
std::string includeHint(const std::string& name, const std::string& path, const std::string& includingFile) {
  std::error_code error;
  if (fs::exists(path, error)) return "";
  std::string dir = fs::path(includingFile).parent_path().string();
  std::string hint = ": an #include is relative to the including file's directory (" + (dir.empty() ? "." : dir) + ")";
  if (fs::path(name).filename() == "texture_include.cfg")
    hint += "; the course's materials are scenes/texture_include.cfg in raytex's source tree: copy it beside "
            "the scene or #include its path";
  return hint;
}

// What readSceneText returns for a file that is missing, unreadable or not a regular file.
const char* const kCannotOpen = "cannot open";

// Reads the scene file or include `path` whole into `*text`, counting its bytes against what the
// policy lets one scene read: "" when read, kCannotOpen, or the message of a file too large or a
// read that failed.
std::string readSceneText(State& st, const std::string& path, std::string* text) {
  const uint64_t left = st.policy.maxSceneBytes - std::min(st.bytesRead, st.policy.maxSceneBytes);
  std::string why;
  uint64_t size = 0;
  switch (readWholeFile(path, left, text, &why, &size)) {
    case ReadStatus::Read: break;
    case ReadStatus::CannotOpen: return kCannotOpen;
    case ReadStatus::ReadFailed: return "cannot read '" + path + "': " + why;
    case ReadStatus::TooLarge: {
      const uint64_t mib = st.policy.maxSceneBytes >> 20;
      return "'" + path + "' (" + std::to_string(size) + " bytes) would bring the scene's files over " +
             std::to_string(mib) + " MiB, the most a scene may read (--max-scene-mib N)";
    }
  }
  st.bytesRead += text->size();
  return "";
}

// Words that cannot name a material (they would read as keys or blocks).
bool isReserved(const std::string& w) {
  static const char* const words[] = {"sphere", "plane", "camera",    "light",    "material", "render", "background",
                                      "ambient_light", "center", "radius", "normal", "distance", "tex_scale",
                                      "tex_rotate", "tex_offset", "texture"};
  for (const char* r : words)
    if (w == r) return true;
  return isNonFiniteWord(w);
}

bool isBlockKeyword(const std::string& w) {
  return w == "sphere" || w == "plane" || w == "camera" || w == "light" || w == "material" || w == "render";
}

class Parser {
 public:
  Parser(State& st, const std::string& text, const std::string& file) : st_(st), tok_(text, file), file_(file) {}

  void parseFile() {
    for (;;) {
      const Token& t = peek();
      if (t.kind == Tok::End) return;
      if (t.kind == Tok::Include) {
        parseInclude();
        continue;
      }
      if (t.kind != Tok::Ident)
        fail(t.loc, "expected sphere, plane, material, camera, light, render, background, ambient_light or #include, got " +
                        describe(t));
      Token kw = take();
      if (kw.text == "sphere") parseSphere(kw);
      else if (kw.text == "plane") parsePlane(kw);
      else if (kw.text == "material") parseMaterial();
      else if (kw.text == "camera") parseCamera(kw);
      else if (kw.text == "light") parseLight(kw);
      else if (kw.text == "render") parseRender(kw);
      else if (kw.text == "background") topColor(kw, &st_.scene.background, &st_.backgroundLoc);
      else if (kw.text == "ambient_light") topColor(kw, &st_.scene.ambientLight, &st_.ambientLoc);
      else unknownKeyword(kw);
    }
  }

 private:
  using Seen = std::map<std::string, FileLoc>;

  const Token& peek(size_t k = 0) {
    while (ahead_.size() <= k) ahead_.push_back(tok_.next());  // deque: references stay valid
    return ahead_[k];
  }

  Token take() {
    peek();
    Token t = std::move(ahead_.front());
    ahead_.pop_front();
    prevEnd_ = t.loc;
    prevEnd_.column += t.length;
    return t;
  }

  Token expect(Tok kind, const std::string& what) {
    if (peek().kind != kind) fail(peek().loc, "expected " + what + ", got " + describe(peek()));
    return take();
  }

  // A missing ';' is reported just after the end of the previous token.
  void semicolon(const std::string& after) {
    if (peek().kind != Tok::Semi) fail(prevEnd_, "expected ';' after " + after + ", got " + describe(peek()));
    take();
  }

  // After a key: '=' then a duplicate check.
  void assign(const Token& key, Seen& seen, const std::string& where) {
    expect(Tok::Equals, "'=' after " + quote(key.text));
    auto it = seen.find(key.text);
    if (it != seen.end())
      fail(key.loc, "duplicate key " + quote(key.text) + " in " + where + " (first given at " + locString(it->second) + ")");
    seen[key.text] = key.loc;
  }

  double number(FileLoc* loc = nullptr, std::string* text = nullptr) {
    const Token& t = peek();
    if (t.kind == Tok::Ident && isNonFiniteWord(t.text)) fail(t.loc, quote(t.text) + " is not a finite number");
    if (t.kind != Tok::Number) fail(t.loc, "expected a number, got " + describe(t));
    if (loc) *loc = t.loc;
    if (text) *text = cfg::clip(t.text);  // quoted in range messages
    return take().number;
  }

  glm::dvec3 tuple(FileLoc* loc = nullptr) {
    return tupleOf([&] { return number(); }, loc);
  }

  // A tuple of the numbers `element` reads.
  template <typename Element>
  glm::dvec3 tupleOf(Element element, FileLoc* loc = nullptr) {
    Token open = expect(Tok::LParen, "a tuple '(x, y, z)'");
    if (loc) *loc = open.loc;
    std::vector<double> v;
    if (peek().kind != Tok::RParen) {
      for (;;) {
        v.push_back(element());
        if (peek().kind == Tok::RParen) break;
        expect(Tok::Comma, "',' or ')' in tuple");
      }
    }
    take();
    if (v.size() != 3) fail(open.loc, "expected 3 numbers, got " + std::to_string(v.size()));
    return glm::dvec3(v[0], v[1], v[2]);
  }

  // A coordinate or distance, within kMaxCoordinate (scene_limits.h); `what` names it in the error,
  // which is at the number.
  double coordinate(const std::string& what) {
    FileLoc loc;
    std::string text;
    double v = number(&loc, &text);
    checkCoordinate(v, loc, what + " " + text);
    return v;
  }

  static void checkCoordinate(double v, const FileLoc& loc, const std::string& what) {
    static_assert(kMaxCoordinate == 1e18, "the message states the limit");
    if (std::fabs(v) > kMaxCoordinate)
      fail(loc, what + " is out of range: raytex renders coordinates and distances from -1e18 to 1e18 (its float "
                       "arithmetic squares distances, which overflows from about 1.8e19)");
  }

  // A position: a tuple of coordinates.
  glm::dvec3 position(const std::string& what, FileLoc* loc = nullptr) {
    return tupleOf([&] { return coordinate(what + " coordinate"); }, loc);
  }

  glm::vec3 color() {
    FileLoc loc;
    glm::vec3 c = glm::vec3(tuple(&loc));
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) fail(loc, "colour components must be >= 0");
    return c;
  }

  double positive(const std::string& what, FileLoc* loc = nullptr, std::string* text = nullptr) {
    FileLoc at;
    std::string written;
    double v = number(&at, &written);
    if (!(v > 0.0)) fail(at, what + " must be > 0, got " + written);
    if (loc) *loc = at;
    if (text) *text = written;
    return v;
  }

  // "{ statement* }" with an optional ';' after the '}'. stmt(key) handles a statement
  // that starts with the identifier `key` (already taken).
  template <typename F>
  void block(const std::string& what, F stmt) {
    Token open = expect(Tok::LBrace, "'{' to open the " + what);
    for (;;) {
      const Token& t = peek();
      if (t.kind == Tok::RBrace) break;
      if (t.kind == Tok::End) fail(open.loc, "'{' of " + what + " is never closed");
      if (t.kind == Tok::Include) fail(t.loc, "#include is only allowed at top level");
      if (t.kind != Tok::Ident) fail(t.loc, "expected a key or '}' in " + what + ", got " + describe(t));
      failMaterialKeyword(what);
      if (isBlockKeyword(t.text) && peek(1).kind != Tok::Equals && peek(1).kind != Tok::Semi)
        fail(open.loc, "'{' of " + what + " is never closed (a " + quote(t.text) + " block starts at " +
                           std::to_string(t.loc.line) + ":" + std::to_string(t.loc.column) + ")");
      stmt(take());
    }
    take();
    if (peek().kind == Tok::Semi) take();
  }

  // `material NAME;` inside a sphere or plane reads as a material block left open: say how to
  // write what was meant.
  void failMaterialKeyword(const std::string& what) {
    if (what != "sphere" && what != "plane") return;
    const Token& t = peek();
    if (t.text != "material" || peek(1).kind != Tok::Ident || peek(2).kind != Tok::Semi) return;
    const std::string name = peek(1).text;
    fail(t.loc, "'material " + name + ";' inside a " + what + ": write '" + name + ";' or 'material = " + name + ";'");
  }

  int lookupMaterial(const Token& name) {
    auto it = st_.materialIndex.find(name.text);
    if (it == st_.materialIndex.end()) {
      std::vector<std::string> names;
      for (const Material& m : st_.scene.materials) names.push_back(m.name);
      fail(name.loc, "unknown material " + quote(name.text) + didYouMean(name.text, names));
    }
    return it->second;
  }

  // `material = NAME;` or a bare `NAME;` inside sphere/plane; the last one wins.
  void materialStatement(const Token& key, int* material, const std::string& where) {
    if (key.text == "material") {
      expect(Tok::Equals, "'=' after 'material'");
      *material = lookupMaterial(expect(Tok::Ident, "a material name"));
      semicolon("the material name");
      return;
    }
    if (peek().kind == Tok::Equals)
      fail(key.loc, "unknown key " + quote(key.text) + " in " + where + didYouMean(key.text, objectKeys(where)));
    *material = lookupMaterial(key);
    semicolon("material name " + quote(key.text));
  }

  // tex_rotate, tex_scale or tex_offset in the sphere or plane block `where` (docs/scene-format.md,
  // "Texture placement"); false if `key` is none of them. offsetLoc: where tex_offset's value is.
  bool placementStatement(const Token& key, Seen& seen, const std::string& where, TexturePlacement* place,
                          FileLoc* offsetLoc) {
    if (key.text == "tex_rotate") {
      assign(key, seen, where);
      FileLoc loc;
      place->rotate = tuple(&loc);
      for (int i = 0; i < 3; ++i)
        if (!(std::fabs(place->rotate[i]) <= 360.0)) fail(loc, "tex_rotate angles must be from -360 to 360 degrees");
    } else if (key.text == "tex_scale") {
      assign(key, seen, where);
      place->scale = positive("tex_scale");
    } else if (key.text == "tex_offset") {
      assign(key, seen, where);
      place->offset = tuple(offsetLoc);
    } else {
      return false;
    }
    semicolon("the value of " + quote(key.text));
    return true;
  }

  // A 2D kind reads (u, v) alone: a third offset component would be silently ignored.
  void checkOffset(const TexturePlacement& place, int material, const FileLoc& offsetLoc) {
    TextureKind kind = material < 0 ? TextureKind::None : st_.scene.materials[size_t(material)].texture.kind;
    if (place.offset.z != 0.0 && readsUv(kind))
      fail(offsetLoc, std::string("tex_offset's third component must be 0 on a ") + textureKindName(kind) +
                          " texture (it offsets (u, v) only)");
  }

  void parseSphere(const Token& kw) {
    checkRoomFor(st_.scene.spheres.size(), MAX_SPHERES, "spheres", kw.loc);
    Sphere s;
    s.loc = kw.loc;
    Seen seen;
    FileLoc offsetLoc;
    block("sphere", [&](const Token& key) {
      if (key.text == "center") {
        assign(key, seen, "sphere");
        s.center = position("sphere center");
      } else if (key.text == "radius") {
        assign(key, seen, "sphere");
        FileLoc loc;
        std::string text;
        s.radius = positive("sphere radius", &loc, &text);
        checkCoordinate(s.radius, loc, "sphere radius " + text);
      } else {
        if (!placementStatement(key, seen, "sphere", &s.placement, &offsetLoc))
          materialStatement(key, &s.material, "sphere");
        return;
      }
      semicolon("the value of " + quote(key.text));
    });
    checkOffset(s.placement, s.material, offsetLoc);
    st_.scene.spheres.push_back(s);
  }

  void parsePlane(const Token& kw) {
    checkRoomFor(st_.scene.planes.size(), MAX_PLANES, "planes", kw.loc);
    Plane p;
    p.loc = kw.loc;
    Seen seen;
    FileLoc offsetLoc;
    block("plane", [&](const Token& key) {
      if (key.text == "normal") {
        assign(key, seen, "plane");
        FileLoc loc;
        glm::dvec3 n = tuple(&loc);
        double len = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
        if (!(len > 0.0)) fail(loc, "plane normal must not be zero");
        p.normal = n / len;
      } else if (key.text == "distance") {
        assign(key, seen, "plane");
        p.distance = coordinate("plane distance");
      } else {
        if (!placementStatement(key, seen, "plane", &p.placement, &offsetLoc))
          materialStatement(key, &p.material, "plane");
        return;
      }
      semicolon("the value of " + quote(key.text));
    });
    checkOffset(p.placement, p.material, offsetLoc);
    st_.scene.planes.push_back(p);
  }

  // Texture placement belongs to an object: the same material may sit on objects placed differently.
  void failPlacementKey(const Token& key, const std::string& where) {
    if (key.text == "tex_rotate" || key.text == "tex_scale" || key.text == "tex_offset")
      fail(key.loc, quote(key.text) + " is not a key of " + where + ": texture placement belongs in the sphere or plane block");
  }

  void parseMaterial() {
    checkRoomFor(st_.scene.materials.size(), kMaxMaterialDefinitions, "materials", peek().loc);
    Token name = expect(Tok::Ident, "a material name after 'material'");
    if (isReserved(name.text)) fail(name.loc, quote(name.text) + " is a reserved word and cannot name a material");
    auto it = st_.materialIndex.find(name.text);
    if (it != st_.materialIndex.end())
      fail(name.loc, "duplicate material " + quote(name.text) + " (first defined at " +
                         locString(st_.scene.materials[size_t(it->second)].loc) + ")");
    Material m = defaultMaterial();
    m.name = name.text;
    m.loc = name.loc;
    Seen seen;
    std::string where = "material " + quote(name.text);
    block(where, [&](const Token& key) {
      if (key.text == "ambient" || key.text == "diffuse" || key.text == "specular") {
        assign(key, seen, where);
        glm::vec3 c = color();
        (key.text == "ambient" ? m.ambient : key.text == "diffuse" ? m.diffuse : m.specular) = c;
      } else if (key.text == "shininess") {
        assign(key, seen, where);
        FileLoc loc;
        std::string text;
        double v = number(&loc, &text);
        if (v < 0.0) fail(loc, "shininess must be >= 0, got " + text);
        m.shininess = float(v);
      } else if (key.text == "texture") {
        assign(key, seen, where);
        m.texture = parseTexture();
        return;
      } else {
        failPlacementKey(key, where);
        fail(key.loc, "unknown key " + quote(key.text) + " in " + where + didYouMean(key.text, kMaterialKeys));
      }
      semicolon("the value of " + quote(key.text));
    });
    st_.materialIndex[m.name] = int(st_.scene.materials.size());
    st_.scene.materials.push_back(m);
  }

  // KIND { key = value; ... } [;]   or   KIND;  the kind's keys from its row (texture_kinds.h).
  TextureDesc parseTexture() {
    Token kindTok = expect(Tok::Ident, "a texture kind after 'texture ='");
    const TextureKindInfo* info = findTextureKind(kindTok.text);
    if (!info) {
      const std::string near = didYouMean(kindTok.text, kindNames());
      fail(kindTok.loc, "unknown texture kind " + quote(kindTok.text) +
                            (near.empty() ? " (expected " + textureKindList() + ")" : near));
    }
    TextureDesc t = info->defaults;
    t.loc = kindTok.loc;
    std::string where = std::string(info->name) + " texture";
    if (peek().kind == Tok::Semi) {
      take();
    } else {
      Seen seen;
      block(where, [&](const Token& key) {
        const TextureKey* k = findKindKey(*info, key.text);
        if (!k && !findTextureKey(key.text)) {
          failPlacementKey(key, where);
          fail(key.loc, "unknown key " + quote(key.text) + " in " + where + didYouMean(key.text, kindKeys(*info)));
        }
        if (!k) fail(key.loc, "'" + key.text + "' does not apply to " + info->name + " textures");
        assign(key, seen, where);
        textureValue(*k, &t);
        semicolon("the value of " + quote(key.text));
      });
    }
    for (const TextureKey& k : info->keys)
      if (k.type == KeyType::File && t.imagePath.empty())
        fail(kindTok.loc, std::string(info->name) + " texture needs '" + k.name + " = \"path\";'");
    return t;
  }

  // The value of texture key k, checked against its row.
  void textureValue(const TextureKey& k, TextureDesc* t) {
    if (k.type == KeyType::Colour) {
      t->*k.colour = color();
      return;
    }
    if (k.type == KeyType::Word) {
      Token v = take();
      for (size_t i = 0; v.kind == Tok::Ident && i < k.words.size(); ++i)
        if (v.text == k.words[i]) return k.setWord(*t, i);
      fail(v.loc, std::string(k.name) + " must be " + describeWords(k) + ", got " + describe(v));
    }
    if (k.type == KeyType::File) {
      Token f = expect(Tok::String, "a file name in quotes");
      if (f.text.empty()) fail(f.loc, "empty file name");
      t->imagePath = (fs::path(file_).parent_path() / f.text).lexically_normal().string();
      checkReadable(st_, f, t->imagePath);
      t->loc = f.loc;
      return;
    }
    FileLoc loc;
    std::string text;
    double v = number(&loc, &text);
    if (!inRange(k.range, v)) fail(loc, std::string(k.name) + " must be " + describeRange(k.range) + ", got " + text);
    if (k.type == KeyType::Whole) t->*k.whole = int(v);
    else t->*k.number = float(v);
  }

  void parseCamera(const Token& kw) {
    if (st_.cameraLoc.line > 0) fail(kw.loc, "duplicate camera (first defined at " + locString(st_.cameraLoc) + ")");
    st_.cameraLoc = kw.loc;
    Camera& c = st_.scene.camera;
    FileLoc eyeLoc = kw.loc, lookatLoc = kw.loc, upLoc = kw.loc;
    Seen seen;
    block("camera", [&](const Token& key) {
      assignKnown(key, seen, "camera", {"eye", "lookat", "up", "fov"});
      if (key.text == "eye") {
        c.eye = position("camera eye", &eyeLoc);
      } else if (key.text == "lookat") {
        c.lookat = position("camera lookat", &lookatLoc);
      } else if (key.text == "up") {
        c.up = tuple(&upLoc);
      } else {
        FileLoc loc;
        std::string text;
        double v = number(&loc, &text);
        if (!(v > 0.0 && v < 180.0)) fail(loc, "fov must be between 0 and 180 degrees (exclusive), got " + text);
        c.fovY = v;
      }
      semicolon("the value of " + quote(key.text));
    });
    glm::dvec3 dir = glm::dvec3(c.lookat) - glm::dvec3(c.eye);
    if (!(glm::length(dir) > 0.0)) {
      bool lookatLater = std::make_pair(lookatLoc.line, lookatLoc.column) > std::make_pair(eyeLoc.line, eyeLoc.column);
      fail(lookatLater ? lookatLoc : eyeLoc, "camera eye and lookat must differ");
    }
    glm::dvec3 up(c.up);
    double upLen = glm::length(up);
    if (!(upLen > 0.0) || glm::length(glm::cross(dir / glm::length(dir), up / upLen)) < 1e-6)
      fail(upLoc, "camera up must be non-zero and not parallel to the view direction");
  }

  // render { width = W; height = H; spp = N; filter = point|box|coverage; image_filter = METHOD; }
  void parseRender(const Token& kw) {
    if (st_.renderLoc.line > 0) fail(kw.loc, "duplicate render (first defined at " + locString(st_.renderLoc) + ")");
    st_.renderLoc = kw.loc;
    RenderSettings& r = st_.scene.render;
    Seen seen;
    block("render", [&](const Token& key) {
      assignKnown(key, seen, "render", {"width", "height", "spp", "filter", "image_filter"});
      if (key.text == "filter") {
        Token v = take();
        std::optional<TextureFilter> filter = v.kind == Tok::Ident ? textureFilterNamed(v.text) : std::nullopt;
        if (!filter) fail(v.loc, "filter must be point, box or coverage, got " + describe(v));
        r.filter = filter;
      } else if (key.text == "image_filter") {
        Token v = take();
        std::optional<ImageFilter> filter = v.kind == Tok::Ident ? imageFilterNamed(v.text) : std::nullopt;
        if (!filter) fail(v.loc, "image_filter must be anisotropic, trilinear, bilinear, ewa or stochastic, got " + describe(v));
        r.imageFilter = filter;
      } else {
        FileLoc loc;
        std::string text;
        double v = number(&loc, &text);
        bool isSize = key.text != "spp";
        double hi = isSize ? 16384.0 : 4096.0;
        if (!(v >= 1.0 && v <= hi) || v != std::floor(v))
          fail(loc, key.text + " must be a whole number from 1 to " + std::to_string(int(hi)) + ", got " + text);
        int n = int(v);
        if (key.text == "width") r.width = n;
        else if (key.text == "height") r.height = n;
        else {
          int side = int(std::lround(std::sqrt(v)));
          if (side * side != n) fail(loc, "spp must be a square number (1, 4, 9, 16, ...), got " + text);
          r.samplesPerPixel = n;
        }
      }
      semicolon("the value of " + quote(key.text));
    });
  }

  void parseLight(const Token& kw) {
    checkRoomFor(st_.scene.lights.size(), MAX_LIGHTS, "lights", kw.loc);
    Light l;
    l.loc = kw.loc;
    Seen seen;
    block("light", [&](const Token& key) {
      assignKnown(key, seen, "light", {"position", "color"});
      if (key.text == "position") l.position = position("light position");
      else l.color = color();
      semicolon("the value of " + quote(key.text));
    });
    st_.scene.lights.push_back(l);
  }

  void unknownKeyword(const Token& kw) {
    const char* near = nearKeyword(kw.text);
    fail(kw.loc, "unknown top-level keyword " + quote(kw.text) +
                     (near ? std::string(" (did you mean '") + near + "'?)" : std::string()));
  }

  void assignKnown(const Token& key, Seen& seen, const std::string& where, std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (key.text == k) return assign(key, seen, where);
    fail(key.loc, "unknown key " + quote(key.text) + " in " + where +
                      didYouMean(key.text, std::vector<std::string>(keys.begin(), keys.end())));
  }

  void topColor(const Token& kw, glm::vec3* out, FileLoc* given) {
    if (given->line > 0) fail(kw.loc, "duplicate " + kw.text + " (first given at " + locString(*given) + ")");
    *given = kw.loc;
    expect(Tok::Equals, "'=' after " + quote(kw.text));
    *out = color();
    semicolon("the value of " + quote(kw.text));
  }

  void parseInclude() {
    Token directive = take();
    Token name = expect(Tok::String, "a file name in quotes after #include");
    if (name.text.empty()) fail(name.loc, "empty file name");
    std::string path = (fs::path(file_).parent_path() / name.text).string();
    checkReadable(st_, name, path);
    if (st_.includeStack.size() > kMaxIncludeDepth)
      fail(directive.loc, "#include nested more than " + std::to_string(kMaxIncludeDepth) + " levels deep");
    std::string key = canonicalKey(path);
    for (size_t i = 0; i < st_.includeStack.size(); ++i) {
      if (st_.includeStack[i].key != key) continue;
      std::string chain;
      for (size_t j = i; j < st_.includeStack.size(); ++j) chain += st_.includeStack[j].name + " -> ";
      fail(directive.loc, "cyclic #include of '" + path + "' (" + chain + path + ")");
    }
    if (++st_.includes > kMaxIncludes)
      fail(directive.loc, "more than " + std::to_string(kMaxIncludes) + " #include directives in one scene");
    std::string text;
    const std::string error = readSceneText(st_, path, &text);
    if (error == kCannotOpen)
      fail(directive.loc, "cannot open included file '" + path + "'" + includeHint(name.text, path, file_));
    if (!error.empty()) fail(directive.loc, error);
    if (!isSceneText(text, path)) fail(directive.loc, "'" + path + "' is not a scene file");
    st_.scene.files.push_back(path);
    parseText(st_, text, path);
  }

  State& st_;
  cfg::Tokenizer tok_;
  std::string file_;
  std::deque<Token> ahead_;
  FileLoc prevEnd_;
};

void parseText(State& st, const std::string& text, const std::string& file) {
  st.includeStack.push_back(OpenFile{canonicalKey(file), file});
  Parser(st, text, file).parseFile();
  st.includeStack.pop_back();
}

// Parses `text` as the file `fileName`, the top of a scene.
Scene parseTop(State& st, const std::string& text, const std::string& fileName) {
  st.scene.path = fileName;
  parseText(st, text, fileName);
  return std::move(st.scene);
}

}  // namespace

Scene parseSceneText(const std::string& text, const std::string& fileName, const ReadPolicy& policy) {
  State st;
  st.policy = policy;
  return parseTop(st, text, fileName);
}

Scene parseSceneFile(const std::string& path, const ReadPolicy& policy) {
  State st;
  st.policy = policy;
  std::string text;
  const std::string error = readSceneText(st, path, &text);
  if (error == kCannotOpen) throw SceneError(FileLoc{path, 0, 0}, "cannot open scene file '" + path + "'");
  if (!error.empty()) throw SceneError(FileLoc{path, 1, 1}, error);
  // The path may come from an untrusted caller too: a file that is not a scene is not quoted.
  if (!isSceneText(text, path)) throw SceneError(FileLoc{path, 1, 1}, "'" + path + "' is not a scene file");
  Scene scene = parseTop(st, text, path);
  // A file with no object would render the background alone: an empty file, or a material
  // library given by mistake, not an image anyone wants.
  if (scene.spheres.empty() && scene.planes.empty())
    throw SceneError(FileLoc{path, 1, 1}, "nothing to render: the scene has no sphere or plane");
  checkSceneLimits(scene);
  scene.files.insert(scene.files.begin(), path);
  return scene;
}
