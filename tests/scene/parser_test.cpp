// Tests of the .cfg scene parser (host/scene/parser.cpp): the course files, syntax, every error
// with its exact file:line:col, includes, and a robustness run over mutated input.
#include "parser.h"
#include "texture_kinds.h"

#include "support/course_scene.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const std::string kTexturesCfg = kSourceDir + "/scenes/textures.cfg";

// The message of the SceneError that parsing `text` as `file` throws, or "<no error>".
std::string errorOf(const std::string& text, const std::string& file = "t.cfg") {
  try {
    parseSceneText(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "<no error>";
}

std::string fileErrorOf(const std::string& path) {
  try {
    parseSceneFile(path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "<no error>";
}

void expectVec(const glm::vec3& v, float x, float y, float z) {
  EXPECT_FLOAT_EQ(v.x, x);
  EXPECT_FLOAT_EQ(v.y, y);
  EXPECT_FLOAT_EQ(v.z, z);
}

// A fresh directory under the system temp dir, removed afterwards.
class ParserFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshTempDir(std::string("parser_test_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    writeFile(dir_ / name, text);
    return path(name);
  }
  fs::path dir_;
};

// Copied verbatim from the course notes (docs digest, "Scene files").
const char* kNotesExcerpt = R"(/* ... (omitted) ... */

sphere {
    center = (0, 0, 0);
    radius = 2.0;

    /* textures predefined in "texture_include.cfg" */
    aSolidChecker;
    // aNoise;
    // aMarble;
    // aWood;
    // anImage;
    // aTurbulence;
    // aDturbulence;
}

plane
{
    normal = (0,1,0);
    distance = -2.0;

    tex_scale = 5.0;

    aChecker;
}

/* ... (omitted) ... */
)";

const char* kAlternatives[] = {"aNoise", "aMarble", "aWood", "anImage", "aTurbulence", "aDturbulence"};

}  // namespace

// ---------------------------------------------------------------- course files

TEST(ParserNotes, ExcerptVerbatimWithIncludedMaterials) {
  // Parsed as if it were a file in scenes/, so the include resolves next to it.
  std::string text = std::string("#include \"texture_include.cfg\"\n") + kNotesExcerpt;
  Scene s = parseSceneText(text, kSourceDir + "/scenes/notes_excerpt.cfg");
  ASSERT_EQ(s.spheres.size(), 1u);
  ASSERT_EQ(s.planes.size(), 1u);
  expectVec(s.spheres[0].center, 0, 0, 0);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 2.0f);
  EXPECT_EQ(s.spheres[0].material, materialIndex(s, "aSolidChecker"));
  expectVec(s.planes[0].normal, 0, 1, 0);
  EXPECT_FLOAT_EQ(s.planes[0].distance, -2.0f);
  EXPECT_FLOAT_EQ(s.planes[0].placement.scale, 5.0f);
  EXPECT_EQ(s.planes[0].material, materialIndex(s, "aChecker"));
  EXPECT_EQ(s.spheres[0].loc.line, 4);  // after the include line and the comment
  EXPECT_EQ(s.planes[0].loc.line, 18);
}

TEST(ParserNotes, ExcerptVerbatimWithMaterialsPrepended) {
  std::string mats =
      "material aSolidChecker { texture = solid_checker { } }\n"
      "material aChecker { texture = checker; }\n";
  Scene s = parseSceneText(mats + kNotesExcerpt, "notes.cfg");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.spheres[0].material, 0);
  EXPECT_EQ(s.planes[0].material, 1);
  EXPECT_EQ(s.materials[1].texture.kind, TextureKind::Checker);
}

TEST(ParserScenes, TexturesCfg) {
  Scene s = parseSceneFile(kTexturesCfg);
  EXPECT_EQ(s.path, kTexturesCfg);
  ASSERT_EQ(s.spheres.size(), 1u);
  ASSERT_EQ(s.planes.size(), 1u);
  expectVec(s.spheres[0].center, 0, 0, 0);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 2.0f);
  ASSERT_GE(s.spheres[0].material, 0);
  EXPECT_EQ(s.materials[size_t(s.spheres[0].material)].name, "aSolidChecker");
  expectVec(s.planes[0].normal, 0, 1, 0);
  EXPECT_FLOAT_EQ(s.planes[0].distance, -2.0f);
  EXPECT_FLOAT_EQ(s.planes[0].placement.scale, 5.0f);
  ASSERT_GE(s.planes[0].material, 0);
  EXPECT_EQ(s.materials[size_t(s.planes[0].material)].name, "aChecker");

  const std::pair<const char*, TextureKind> expected[] = {
      {"aChecker", TextureKind::Checker},       {"aSolidChecker", TextureKind::SolidChecker},
      {"aNoise", TextureKind::Noise},           {"aMarble", TextureKind::Marble},
      {"aWood", TextureKind::Wood},             {"anImage", TextureKind::Image},
      {"aTurbulence", TextureKind::Turbulence}, {"aDturbulence", TextureKind::DTurbulence},
  };
  ASSERT_EQ(s.materials.size(), 8u);
  for (const auto& [name, kind] : expected) {
    int i = materialIndex(s, name);
    ASSERT_GE(i, 0) << name;
    const Material& m = s.materials[size_t(i)];
    EXPECT_EQ(m.texture.kind, kind) << name;
    EXPECT_EQ(m.loc.file, kSourceDir + "/scenes/texture_include.cfg") << name;
    EXPECT_GT(m.shininess, 0.0f) << name;
  }
  // Image paths are joined to the directory of the file naming them, then lexically normalised.
  const Material& img = s.materials[size_t(materialIndex(s, "anImage"))];
  EXPECT_EQ(img.texture.imagePath, (fs::path(kSourceDir) / "textures/earth.jpg").lexically_normal().string());
  EXPECT_EQ(img.texture.loc.file, kSourceDir + "/scenes/texture_include.cfg");
  EXPECT_GT(img.texture.loc.line, 0);

  EXPECT_EQ(s.lights.size(), 1u);
  // The field of view the file writes, read from its text rather than by the tokenizer (the
  // parser refuses any fov outside (0, 180), so a range check here could not fail).
  const std::string text = readFile(kTexturesCfg);
  size_t fov = text.find("fov");
  while (fov != std::string::npos && fov > 0 && std::isalnum(static_cast<unsigned char>(text[fov - 1])))
    fov = text.find("fov", fov + 1);
  ASSERT_NE(fov, std::string::npos);
  const size_t equals = text.find_first_not_of(" \t", fov + 3);
  ASSERT_EQ(text[equals], '=');
  EXPECT_DOUBLE_EQ(s.camera.fovY, std::stod(text.substr(equals + 1)));
}

TEST(ParserScenes, SwitchingTheSphereMaterialByCommenting) {
  const std::string original = readFile(kTexturesCfg);
  size_t sphere = original.find("sphere {");
  ASSERT_NE(sphere, std::string::npos);
  for (const char* name : kAlternatives) {
    std::string text = original;
    size_t on = text.find("    aSolidChecker;", sphere);
    ASSERT_NE(on, std::string::npos);
    text.replace(on, 4, "    // ");
    std::string commented = std::string("// ") + name + ";";
    size_t off = text.find(commented, sphere);
    ASSERT_NE(off, std::string::npos) << name;
    text.erase(off, 3);
    Scene s = parseSceneText(text, kTexturesCfg);
    ASSERT_EQ(s.spheres.size(), 1u);
    ASSERT_GE(s.spheres[0].material, 0) << name;
    EXPECT_EQ(s.materials[size_t(s.spheres[0].material)].name, name);
    EXPECT_EQ(s.materials[size_t(s.planes[0].material)].name, "aChecker");
  }
}

TEST(ParserScenes, LastMaterialNamedWins) {
  std::string text = readFile(kTexturesCfg);
  size_t at = text.find("// aMarble;");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, 3);  // now both aSolidChecker and aMarble are named
  Scene s = parseSceneText(text, kTexturesCfg);
  EXPECT_EQ(s.materials[size_t(s.spheres[0].material)].name, "aMarble");
}

// ---------------------------------------------------------------- syntax

TEST(ParserSyntax, BraceOnSameOrNextLineAndCommentsEverywhere) {
  Scene s = parseSceneText(
      "// line comment\n"
      "material /* inline */ m // trailing\n"
      "{\n"
      "  /* multi\n"
      "     line */ diffuse = (0.5, /* mid-tuple */ 0.25, 0.125); // after\n"
      "}\n"
      "sphere\n"
      "\n"
      "{ radius = 3; m; }\n"
      "plane { material = m; }\n"
      "/**/ /***/ /* * / */\n",
      "t.cfg");
  ASSERT_EQ(s.materials.size(), 1u);
  expectVec(s.materials[0].diffuse, 0.5f, 0.25f, 0.125f);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 3.0f);
  EXPECT_EQ(s.spheres[0].material, 0);
  EXPECT_EQ(s.planes[0].material, 0);
  EXPECT_EQ(s.spheres[0].loc.line, 7);
  EXPECT_EQ(s.spheres[0].loc.column, 1);
}

TEST(ParserSyntax, NumbersSignsExponents) {
  Scene s = parseSceneText(
      "sphere { center = (+1, -2.5, .5); radius = 1e-3; }\n"
      "sphere { center = (1E2, -1.5e+1, 5.); radius = 2.5E0; }\n"
      "plane { distance = -0; tex_scale = 0.25; }\n"
      "plane { distance = -12e-1; }\n",
      "t.cfg");
  ASSERT_EQ(s.spheres.size(), 2u);
  expectVec(s.spheres[0].center, 1.0f, -2.5f, 0.5f);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 0.001f);
  expectVec(s.spheres[1].center, 100.0f, -15.0f, 5.0f);
  EXPECT_FLOAT_EQ(s.spheres[1].radius, 2.5f);
  EXPECT_FLOAT_EQ(s.planes[0].distance, 0.0f);
  EXPECT_FLOAT_EQ(s.planes[0].placement.scale, 0.25f);
  EXPECT_FLOAT_EQ(s.planes[1].distance, -1.2f);
}

TEST(ParserSyntax, TupleAcrossLinesAndCrLf) {
  Scene s = parseSceneText("background = (\r\n  0.1,\r\n  0.2 ,\r\n\t0.3\r\n) ;\r\nambient_light=(1,1,1);", "t.cfg");
  expectVec(s.background, 0.1f, 0.2f, 0.3f);
  expectVec(s.ambientLight, 1, 1, 1);
  EXPECT_EQ(errorOf("\r\nsphere {\r\n  radius = 0;\r\n}\r\n"), "t.cfg:3:12: sphere radius must be > 0, got 0");
}

TEST(ParserSyntax, ObjectsWithoutKeysUseDefaults) {
  Scene s = parseSceneText("sphere { }\nplane { }\n", "t.cfg");
  Sphere ds;
  Plane dp;
  EXPECT_FLOAT_EQ(s.spheres[0].radius, ds.radius);
  EXPECT_EQ(s.spheres[0].material, -1);
  expectVec(s.planes[0].normal, dp.normal.x, dp.normal.y, dp.normal.z);
  EXPECT_FLOAT_EQ(s.planes[0].placement.scale, 1.0f);
  EXPECT_EQ(s.planes[0].material, -1);
  EXPECT_TRUE(s.materials.empty());
  EXPECT_TRUE(s.lights.empty());
}

TEST(ParserSyntax, PlaneNormalIsNormalised) {
  Scene s = parseSceneText("plane { normal = (0, 3, 4); }", "t.cfg");
  expectVec(s.planes[0].normal, 0.0f, 0.6f, 0.8f);
}

TEST(ParserSyntax, MaterialDefaultsAndOverrides) {
  Scene s = parseSceneText(
      "material plain { }\n"
      "material shiny { specular = (1, 1, 1); shininess = 100; ambient = (0,0,0); }\n",
      "t.cfg");
  Material d = defaultMaterial();
  const Material& p = s.materials[0];
  EXPECT_EQ(p.name, "plain");
  expectVec(p.ambient, d.ambient.x, d.ambient.y, d.ambient.z);
  expectVec(p.diffuse, d.diffuse.x, d.diffuse.y, d.diffuse.z);
  EXPECT_FLOAT_EQ(p.shininess, d.shininess);
  EXPECT_EQ(p.texture.kind, TextureKind::None);
  EXPECT_EQ(p.loc.line, 1);
  EXPECT_EQ(p.loc.column, 10);
  const Material& q = s.materials[1];
  expectVec(q.specular, 1, 1, 1);
  expectVec(q.ambient, 0, 0, 0);
  expectVec(q.diffuse, d.diffuse.x, d.diffuse.y, d.diffuse.z);
  EXPECT_FLOAT_EQ(q.shininess, 100.0f);
}

TEST(ParserSyntax, TextureKeysOverrideDefaults) {
  Scene s = parseSceneText(
      "material a { texture = marble { color1 = (1, 0, 0); scale = 2; strength = -3; octaves = 5.0; }; }\n"
      "material b { texture = checker { squares = 8; color2 = (0, 0, 1); } }\n"
      "material c { texture = noise { scale = 0.5; } }\n"
      "material d { texture = wood; }\n"
      "material e { texture = dturbulence {} }\n",
      "t.cfg");
  const TextureDesc& a = s.materials[0].texture;
  TextureDesc am = defaultTexture(TextureKind::Marble);
  EXPECT_EQ(a.kind, TextureKind::Marble);
  expectVec(a.color1, 1, 0, 0);
  expectVec(a.color2, am.color2.x, am.color2.y, am.color2.z);
  EXPECT_FLOAT_EQ(a.scale, 2.0f);
  EXPECT_FLOAT_EQ(a.strength, -3.0f);
  EXPECT_EQ(a.octaves, 5);
  EXPECT_EQ(a.loc.line, 1);
  EXPECT_EQ(a.loc.column, 24);
  const TextureDesc& b = s.materials[1].texture;
  TextureDesc bc = defaultTexture(TextureKind::Checker);
  EXPECT_FLOAT_EQ(b.squares, 8.0f);
  expectVec(b.color1, bc.color1.x, bc.color1.y, bc.color1.z);
  expectVec(b.color2, 0, 0, 1);
  EXPECT_FLOAT_EQ(s.materials[2].texture.scale, 0.5f);
  TextureDesc wd = defaultTexture(TextureKind::Wood);
  EXPECT_EQ(s.materials[3].texture.kind, TextureKind::Wood);
  EXPECT_FLOAT_EQ(s.materials[3].texture.scale, wd.scale);
  EXPECT_EQ(s.materials[3].texture.octaves, wd.octaves);
  EXPECT_EQ(s.materials[4].texture.kind, TextureKind::DTurbulence);
}

TEST(ParserSyntax, CameraLightsBackground) {
  Scene s = parseSceneText(
      "camera { eye = (1, 2, 3); lookat = (0, 1, 0); up = (0, 1, 0); fov = 40; }\n"
      "light { position = (1, 10, 1); color = (0.5, 0.5, 0.5); }\n"
      "light { position = (-1, 5, 0); }\n"
      "background = (0.2, 0.3, 0.4);\n"
      "ambient_light = (0.5, 0.5, 0.5);\n",
      "t.cfg");
  expectVec(s.camera.eye, 1, 2, 3);
  expectVec(s.camera.lookat, 0, 1, 0);
  expectVec(s.camera.up, 0, 1, 0);
  EXPECT_FLOAT_EQ(s.camera.fovY, 40.0f);
  ASSERT_EQ(s.lights.size(), 2u);
  expectVec(s.lights[0].color, 0.5f, 0.5f, 0.5f);
  expectVec(s.lights[1].position, -1, 5, 0);
  expectVec(s.lights[1].color, 1, 1, 1);
  expectVec(s.background, 0.2f, 0.3f, 0.4f);
  expectVec(s.ambientLight, 0.5f, 0.5f, 0.5f);
}

// ---------------------------------------------------------------- errors

TEST(ParserErrors, UnknownKeys) {
  EXPECT_EQ(errorOf("sphere {\n  radiuss = 2;\n}\n"), "t.cfg:2:3: unknown key 'radiuss' in sphere (did you mean 'radius'?)");
  EXPECT_EQ(errorOf("plane { tex_scal = 2; }"), "t.cfg:1:9: unknown key 'tex_scal' in plane (did you mean 'tex_scale'?)");
  EXPECT_EQ(errorOf("light { colour = (1,1,1); }"), "t.cfg:1:9: unknown key 'colour' in light (did you mean 'color'?)");
  EXPECT_EQ(errorOf("camera { fovy = 30; }"), "t.cfg:1:10: unknown key 'fovy' in camera (did you mean 'fov'?)");
  EXPECT_EQ(errorOf("material m {\n  difuse = (1,1,1);\n}"), "t.cfg:2:3: unknown key 'difuse' in material 'm' (did you mean 'diffuse'?)");
  EXPECT_EQ(errorOf("material m { texture = noise { size = 1; } }"),
            "t.cfg:1:32: unknown key 'size' in noise texture");
  // "did you mean": the nearest key of the block, kind, material or top-level keyword within
  // edit distance 2; none further off.
  EXPECT_EQ(errorOf("material m { texture = marble { scal = 2; } }"),
            "t.cfg:1:33: unknown key 'scal' in marble texture (did you mean 'scale'?)");
  EXPECT_EQ(errorOf("render { fliter = box; }"), "t.cfg:1:10: unknown key 'fliter' in render (did you mean 'filter'?)");
  EXPECT_EQ(errorOf("sphere { centre = (0, 0, 0); }"), "t.cfg:1:10: unknown key 'centre' in sphere (did you mean 'center'?)");
  EXPECT_EQ(errorOf("sphere { colour = (0, 0, 0); }"), "t.cfg:1:10: unknown key 'colour' in sphere");
  EXPECT_EQ(errorOf("material marble1 { }\nsphere { marble2; }"),
            "t.cfg:2:10: unknown material 'marble2' (did you mean 'marble1'?)");
  EXPECT_EQ(errorOf("material m { }\nsphere { wood; }"), "t.cfg:2:10: unknown material 'wood'");
  // `material NAME;` in an object, which would read as an unclosed block.
  EXPECT_EQ(errorOf("material red { }\nsphere { radius = 1; material red; }"),
            "t.cfg:2:22: 'material red;' inside a sphere: write 'red;' or 'material = red;'");
  EXPECT_EQ(errorOf("material red { }\nplane { material red; }"),
            "t.cfg:2:9: 'material red;' inside a plane: write 'red;' or 'material = red;'");
}

TEST(ParserErrors, UnknownTopLevelKeyword) {
  EXPECT_EQ(errorOf("\n  spher {\n}\n"), "t.cfg:2:3: unknown top-level keyword 'spher' (did you mean 'sphere'?)");
  EXPECT_EQ(errorOf("sphere { }\nambeint_light = (1, 1, 1);"),
            "t.cfg:2:1: unknown top-level keyword 'ambeint_light' (did you mean 'ambient_light'?)");
  EXPECT_EQ(errorOf("sphere { }\ncube { }"), "t.cfg:2:1: unknown top-level keyword 'cube'");
  EXPECT_EQ(errorOf("radius = 2;"), "t.cfg:1:1: unknown top-level keyword 'radius'");
  EXPECT_EQ(errorOf("sphere { } }"),
            "t.cfg:1:12: expected sphere, plane, material, camera, light, render, background, ambient_light or "
            "#include, got '}'");
}

TEST(ParserErrors, UnknownMaterial) {
  EXPECT_EQ(errorOf("sphere {\n  aFoo;\n}\n"), "t.cfg:2:3: unknown material 'aFoo'");
  EXPECT_EQ(errorOf("sphere { material = aFoo; }"), "t.cfg:1:21: unknown material 'aFoo'");
  // Defined only later in the file: not yet known.
  EXPECT_EQ(errorOf("plane { aM; }\nmaterial aM { }\n"), "t.cfg:1:9: unknown material 'aM'");
}

TEST(ParserErrors, MissingSemicolonIsReportedJustAfterThePreviousToken) {
  EXPECT_EQ(errorOf("sphere {\n  radius = 2.0\n  center = (0,0,0);\n}\n"),
            "t.cfg:2:15: expected ';' after the value of 'radius', got 'center'");
  EXPECT_EQ(errorOf("material m { }\nsphere {\n  m\n}\n"), "t.cfg:3:4: expected ';' after material name 'm', got '}'");
  EXPECT_EQ(errorOf("background = (1,1,1)"),
            "t.cfg:1:21: expected ';' after the value of 'background', got end of file");
  EXPECT_EQ(errorOf("material m { texture = image { file = \"a.png\" } }"),
            "t.cfg:1:46: expected ';' after the value of 'file', got '}'");
}

TEST(ParserErrors, MissingClosingBrace) {
  EXPECT_EQ(errorOf("sphere {\n  radius = 2;\n"), "t.cfg:1:8: '{' of sphere is never closed");
  EXPECT_EQ(errorOf("plane\n{\n  distance = 1;\n"), "t.cfg:2:1: '{' of plane is never closed");
  EXPECT_EQ(errorOf("sphere {\n  radius = 2;\n\nplane {\n}\n"),
            "t.cfg:1:8: '{' of sphere is never closed (a 'plane' block starts at 4:1)");
  EXPECT_EQ(errorOf("material m {\n  texture = checker {\n"), "t.cfg:2:21: '{' of checker texture is never closed");
  EXPECT_EQ(errorOf("sphere radius = 2;"), "t.cfg:1:8: expected '{' to open the sphere, got 'radius'");
}

TEST(ParserErrors, UnterminatedCommentAndString) {
  EXPECT_EQ(errorOf("sphere {\n  /* radius = 2;\n}\n"), "t.cfg:2:3: unterminated comment: '/*' has no matching '*/'");
  EXPECT_EQ(errorOf("/* a */ /* b *"), "t.cfg:1:9: unterminated comment: '/*' has no matching '*/'");
  EXPECT_EQ(errorOf("#include \"abc\n\"x\""),
            "t.cfg:1:10: unterminated string (a string must end with '\"' on the line it starts)");
  EXPECT_EQ(errorOf("material m { texture = image { file = \"a.png"),
            "t.cfg:1:39: unterminated string (a string must end with '\"' on the line it starts)");
}

TEST(ParserErrors, TupleArity) {
  EXPECT_EQ(errorOf("background = (1, 2);"), "t.cfg:1:14: expected 3 numbers, got 2");
  EXPECT_EQ(errorOf("background = (1, 2, 3, 4);"), "t.cfg:1:14: expected 3 numbers, got 4");
  EXPECT_EQ(errorOf("sphere {\n  center =\n  ();\n}"), "t.cfg:3:3: expected 3 numbers, got 0");
  EXPECT_EQ(errorOf("background = (1, 2, 3;"), "t.cfg:1:22: expected ',' or ')' in tuple, got ';'");
  EXPECT_EQ(errorOf("background = 1;"), "t.cfg:1:14: expected a tuple '(x, y, z)', got '1'");
}

TEST(ParserErrors, NumberExpected) {
  EXPECT_EQ(errorOf("sphere { radius = abc; }"), "t.cfg:1:19: expected a number, got 'abc'");
  EXPECT_EQ(errorOf("background = (1, x, 3);"), "t.cfg:1:18: expected a number, got 'x'");
  EXPECT_EQ(errorOf("sphere { radius = (1, 2, 3); }"), "t.cfg:1:19: expected a number, got '('");
  EXPECT_EQ(errorOf("sphere { radius = ; }"), "t.cfg:1:19: expected a number, got ';'");
  EXPECT_EQ(errorOf("sphere { radius 2; }"), "t.cfg:1:17: expected '=' after 'radius', got '2'");
}

TEST(ParserErrors, BadNumbers) {
  EXPECT_EQ(errorOf("sphere { radius = 1e999; }"), "t.cfg:1:19: number '1e999' is out of range");
  EXPECT_EQ(errorOf("sphere { radius = -1e999; }"), "t.cfg:1:19: number '-1e999' is out of range");
  EXPECT_EQ(errorOf("sphere { radius = 1e39; }"), "t.cfg:1:19: number '1e39' is out of range");  // > float max
  EXPECT_EQ(errorOf("sphere { radius = nan; }"), "t.cfg:1:19: 'nan' is not a finite number");
  EXPECT_EQ(errorOf("background = (-inf, 0, 0);"), "t.cfg:1:15: '-inf' is not a finite number");
  EXPECT_EQ(errorOf("background = (0, Infinity, 0);"), "t.cfg:1:18: 'Infinity' is not a finite number");
  EXPECT_EQ(errorOf("sphere { radius = 1.2.3; }"), "t.cfg:1:19: malformed number '1.2.3'");
  EXPECT_EQ(errorOf("sphere { radius = 1e; }"), "t.cfg:1:19: malformed number '1e'");
  EXPECT_EQ(errorOf("sphere { radius = 2x; }"), "t.cfg:1:19: malformed number '2x'");
  EXPECT_EQ(errorOf("sphere { radius = 0x10; }"), "t.cfg:1:19: malformed number '0x10'");
  EXPECT_EQ(errorOf("sphere { radius = - 1; }"), "t.cfg:1:19: unexpected character '-'");
}

TEST(ParserErrors, OutOfRangeValues) {
  EXPECT_EQ(errorOf("plane { normal = (0, 0, 0); }"), "t.cfg:1:18: plane normal must not be zero");
  EXPECT_EQ(errorOf("sphere { radius = -1; }"), "t.cfg:1:19: sphere radius must be > 0, got -1");
  EXPECT_EQ(errorOf("sphere { radius = 0.0; }"), "t.cfg:1:19: sphere radius must be > 0, got 0.0");
  EXPECT_EQ(errorOf("plane { tex_scale = 0; }"), "t.cfg:1:21: tex_scale must be > 0, got 0");
  EXPECT_EQ(errorOf("camera { fov = 180; }"), "t.cfg:1:16: fov must be between 0 and 180 degrees (exclusive), got 180");
  EXPECT_EQ(errorOf("camera { fov = 0; }"), "t.cfg:1:16: fov must be between 0 and 180 degrees (exclusive), got 0");
  EXPECT_EQ(errorOf("background = (0, -1, 0);"), "t.cfg:1:14: colour components must be >= 0");
  EXPECT_EQ(errorOf("material m { shininess = -1; }"), "t.cfg:1:26: shininess must be >= 0, got -1");
  EXPECT_EQ(errorOf("material m { texture = checker { squares = 0; } }"),
            "t.cfg:1:44: squares must be > 0, got 0");
  EXPECT_EQ(errorOf("material m { texture = noise { scale = -2; } }"), "t.cfg:1:40: scale must be > 0, got -2");
  EXPECT_EQ(errorOf("material m { texture = marble { octaves = 17; } }"),
            "t.cfg:1:43: octaves must be a whole number from 1 to 16, got 17");
  EXPECT_EQ(errorOf("material m { texture = marble { octaves = 2.5; } }"),
            "t.cfg:1:43: octaves must be a whole number from 1 to 16, got 2.5");
  EXPECT_EQ(errorOf("material m { texture = wood { color1 = (1, -0.5, 0); } }"),
            "t.cfg:1:40: colour components must be >= 0");
}

// Positions and distances past kMaxCoordinate (scene_limits.h): the kernel's float arithmetic
// squares distances between them, which overflows from about 1.8e19 (a sphere at 2e19 rendered
// unlit, at 3e19 not at all; a plane at distance 1e20 unlit). The error is at the number.
TEST(ParserErrors, CoordinatesPastTheLimit) {
  const std::string range =
      " is out of range: raytex renders coordinates and distances from -1e18 to 1e18 (its float arithmetic "
      "squares distances, which overflows from about 1.8e19)";
  EXPECT_EQ(errorOf("sphere { center = (0, 0, 2e19); }"), "t.cfg:1:26: sphere center coordinate 2e19" + range);
  EXPECT_EQ(errorOf("sphere { center = (-3e19, 0, 0); }"), "t.cfg:1:20: sphere center coordinate -3e19" + range);
  EXPECT_EQ(errorOf("sphere { radius = 3e19; }"), "t.cfg:1:19: sphere radius 3e19" + range);
  EXPECT_EQ(errorOf("plane { distance = 1e20; }"), "t.cfg:1:20: plane distance 1e20" + range);
  EXPECT_EQ(errorOf("plane { distance = -1.000001e18; }"), "t.cfg:1:20: plane distance -1.000001e18" + range);
  EXPECT_EQ(errorOf("camera { eye = (0, 2e18, 0); }"), "t.cfg:1:20: camera eye coordinate 2e18" + range);
  EXPECT_EQ(errorOf("camera { lookat = (0, 0, -5e37); }"), "t.cfg:1:26: camera lookat coordinate -5e37" + range);
  EXPECT_EQ(errorOf("light { position = (1e30, 0, 0); }"), "t.cfg:1:21: light position coordinate 1e30" + range);
  // At the limit every value parses.
  const Scene scene = parseSceneText(
      "camera { eye = (-1e18, -1e18, -1e18); lookat = (1e18, 1e18, 1e18); up = (0, 1, 0); }\n"
      "light { position = (-1e18, 1e18, -1e18); }\n"
      "sphere { center = (1e18, 1e18, 1e18); radius = 1e18; }\nplane { normal = (0, 0, 1); distance = -1e18; }\n",
      "t.cfg");
  EXPECT_EQ(scene.spheres[0].radius, 1e18);
  EXPECT_EQ(scene.planes[0].distance, -1e18);
}

TEST(ParserErrors, Camera) {
  EXPECT_EQ(errorOf("camera {\n  eye = (1, 2, 3);\n  lookat = (1, 2, 3);\n}\n"),
            "t.cfg:3:12: camera eye and lookat must differ");
  EXPECT_EQ(errorOf("camera {\n  lookat = (0, 0, 10);\n}\n"), "t.cfg:2:12: camera eye and lookat must differ");
  EXPECT_EQ(errorOf("camera {\n  eye = (0, 5, 0);\n  lookat = (0, 0, 0);\n}\n"),
            "t.cfg:1:1: camera up must be non-zero and not parallel to the view direction");
  EXPECT_EQ(errorOf("camera {\n  up = (0, 2, 0);\n  eye = (0, 5, 0);\n}\n"),
            "t.cfg:2:8: camera up must be non-zero and not parallel to the view direction");
  EXPECT_EQ(errorOf("camera { up = (0, 0, 0); }"),
            "t.cfg:1:15: camera up must be non-zero and not parallel to the view direction");
}

TEST(ParserErrors, Duplicates) {
  EXPECT_EQ(errorOf("material m { }\nmaterial m { }\n"), "t.cfg:2:10: duplicate material 'm' (first defined at t.cfg:1:10)");
  EXPECT_EQ(errorOf("sphere {\n  radius = 1;\n  radius = 2;\n}\n"),
            "t.cfg:3:3: duplicate key 'radius' in sphere (first given at t.cfg:2:3)");
  EXPECT_EQ(errorOf("material m { texture = checker; texture = noise; }"),
            "t.cfg:1:33: duplicate key 'texture' in material 'm' (first given at t.cfg:1:14)");
  EXPECT_EQ(errorOf("camera { }\ncamera { }\n"), "t.cfg:2:1: duplicate camera (first defined at t.cfg:1:1)");
  EXPECT_EQ(errorOf("background = (0,0,0);\nbackground = (1,1,1);"),
            "t.cfg:2:1: duplicate background (first given at t.cfg:1:1)");
  EXPECT_EQ(errorOf("ambient_light = (0,0,0);\n ambient_light = (1,1,1);"),
            "t.cfg:2:2: duplicate ambient_light (first given at t.cfg:1:1)");
}

// wrap: repeat by default; clamp or repeat as given.
TEST(Parser, ImageWrap) {
  Scene s = parseSceneText("material a { texture = image { file = \"a.png\"; } }\n"
                           "material b { texture = image { file = \"b.png\"; wrap = clamp; } }\n"
                           "material c { texture = image { wrap = repeat; file = \"c.png\"; } }\n",
                           "t.cfg");
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[0].texture.wrap, ImageWrap::Repeat);
  EXPECT_EQ(s.materials[1].texture.wrap, ImageWrap::Clamp);
  EXPECT_EQ(s.materials[2].texture.wrap, ImageWrap::Repeat);
}

TEST(ParserErrors, Textures) {
  EXPECT_EQ(errorOf("material m {\n  texture = checker {\n    file = \"x.png\";\n  }\n}\n"),
            "t.cfg:3:5: 'file' does not apply to checker textures");
  EXPECT_EQ(errorOf("material m { texture = noise { octaves = 3; } }"),
            "t.cfg:1:32: 'octaves' does not apply to noise textures");
  EXPECT_EQ(errorOf("material m { texture = marble { squares = 3; } }"),
            "t.cfg:1:33: 'squares' does not apply to marble textures");
  EXPECT_EQ(errorOf("material m { texture = image { file = \"a.png\"; color1 = (1,1,1); } }"),
            "t.cfg:1:48: 'color1' does not apply to image textures");
  EXPECT_EQ(errorOf("material m { texture = solid_checker { scale = 2; } }"),
            "t.cfg:1:40: 'scale' does not apply to solid_checker textures");
  EXPECT_EQ(errorOf("material m { texture = checkr; }"),
            "t.cfg:1:24: unknown texture kind 'checkr' (did you mean 'checker'?)");
  EXPECT_EQ(errorOf("material m { texture = stripes; }"),
            "t.cfg:1:24: unknown texture kind 'stripes' (expected " + textureKindList() + ")");
  EXPECT_EQ(errorOf("material m { texture = image { } }"), "t.cfg:1:24: image texture needs 'file = \"path\";'");
  EXPECT_EQ(errorOf("material m { texture = checker { wrap = clamp; } }"),
            "t.cfg:1:34: 'wrap' does not apply to checker textures");
  EXPECT_EQ(errorOf("material m { texture = image { file = \"a.png\"; wrap = mirror; } }"),
            "t.cfg:1:55: wrap must be repeat or clamp, got 'mirror'");
  EXPECT_EQ(errorOf("material m { texture = image { file = \"a.png\"; wrap = 1; } }"),
            "t.cfg:1:55: wrap must be repeat or clamp, got '1'");
  EXPECT_EQ(errorOf("material m { texture = image; }"), "t.cfg:1:24: image texture needs 'file = \"path\";'");
  EXPECT_EQ(errorOf("material m { texture = image { file = \"\"; } }"), "t.cfg:1:39: empty file name");
  EXPECT_EQ(errorOf("material m { texture = image { file = a.png; } }"),
            "t.cfg:1:39: expected a file name in quotes, got 'a'");
}

TEST(ParserErrors, LexicalAndMisc) {
  EXPECT_EQ(errorOf("sphere { radius = 2; } @"), "t.cfg:1:24: unexpected character '@'");
  EXPECT_EQ(errorOf(std::string("sphere {\n \x01 }")), "t.cfg:2:2: unexpected character '\\x01'");
  EXPECT_EQ(errorOf("sphere { / }"), "t.cfg:1:10: unexpected character '/'");
  EXPECT_EQ(errorOf("#define X 1"), "t.cfg:1:1: unknown directive '#define'");
  EXPECT_EQ(errorOf("  # include \"a\""), "t.cfg:1:3: unexpected character '#'");
  EXPECT_EQ(errorOf("sphere {\n  #include \"x.cfg\"\n}"), "t.cfg:2:3: #include is only allowed at top level");
  EXPECT_EQ(errorOf("#include x.cfg"), "t.cfg:1:10: expected a file name in quotes after #include, got 'x'");
  EXPECT_EQ(errorOf("#include \"\""), "t.cfg:1:10: empty file name");
  EXPECT_EQ(errorOf("material radius { }"), "t.cfg:1:10: 'radius' is a reserved word and cannot name a material");
  EXPECT_EQ(errorOf("material { }"), "t.cfg:1:10: expected a material name after 'material', got '{'");
  EXPECT_EQ(errorOf("sphere { radius = 1; ( }"), "t.cfg:1:22: expected a key or '}' in sphere, got '('");
  // A file that cannot be opened has no line: FileLoc line 0, printed as "file: message".
  try {
    parseSceneFile("/nonexistent/raytex/nope.cfg");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc.file, "/nonexistent/raytex/nope.cfg");
    EXPECT_EQ(e.loc.line, 0);
    EXPECT_EQ(std::string(e.what()), formatLoc(e.loc, "cannot open scene file '/nonexistent/raytex/nope.cfg'"));
  }
}

TEST(ParserErrors, ErrorsCarryTheirLocation) {
  try {
    parseSceneText("\n\n   sphere { radius = -2; }", "dir/scene.cfg");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc.file, "dir/scene.cfg");
    EXPECT_EQ(e.loc.line, 3);
    EXPECT_EQ(e.loc.column, 22);
  }
}

// ---------------------------------------------------------------- quoting

// Scene text quoted in a message is cut to 40 bytes, so a message never grows with the input.
TEST(ParserQuoting, HugeTokensGiveShortMessages) {
  const std::string huge(10 * 1024 * 1024, 'a');
  const std::string cut = std::string(40, 'a') + "...";
  EXPECT_EQ(errorOf("sphere { " + huge + " = 1; }"), "t.cfg:1:10: unknown key '" + cut + "' in sphere");
  EXPECT_EQ(errorOf("sphere { " + huge + "; }"), "t.cfg:1:10: unknown material '" + cut + "'");
  EXPECT_EQ(errorOf("sphere { } " + huge + " { }"), "t.cfg:1:12: unknown top-level keyword '" + cut + "'");
  EXPECT_EQ(errorOf("material " + huge + " { x = 1; }"),
            "t.cfg:1:" + std::to_string(13 + huge.size()) + ": unknown key 'x' in material '" + cut + "'");
  EXPECT_EQ(errorOf("#" + huge), "t.cfg:1:1: unknown directive '#" + std::string(39, 'a') + "...'");
  const std::string digits(10 * 1024 * 1024, '1');
  EXPECT_EQ(errorOf("sphere { radius = " + digits + "x; }"),
            "t.cfg:1:19: malformed number '" + std::string(40, '1') + "...'");
  EXPECT_EQ(errorOf("sphere { radius = " + digits + "; }"),
            "t.cfg:1:19: number '" + std::string(40, '1') + "...' is out of range");
  EXPECT_EQ(errorOf("sphere { radius = -0." + digits + "; }"),
            "t.cfg:1:19: sphere radius must be > 0, got -0." + std::string(37, '1') + "...");
  EXPECT_EQ(errorOf("sphere { radius = \"" + huge + "\"; }"),
            "t.cfg:1:19: expected a number, got '\"" + cut + "\"'");
  EXPECT_LT(errorOf("sphere { " + huge + " = 1; }").size(), 300u);
}

TEST(ParserQuoting, CutAtAUtf8CharacterBoundary) {
  // U+20AC EURO SIGN is 3 bytes: 13 of them fill 39 bytes, and the 14th would pass 40.
  std::string euros;
  for (int i = 0; i < 20; ++i) euros += "\xE2\x82\xAC";
  std::string thirteen;
  for (int i = 0; i < 13; ++i) thirteen += "\xE2\x82\xAC";
  EXPECT_EQ(errorOf("sphere { radius = \"" + euros + "\"; }"),
            "t.cfg:1:19: expected a number, got '\"" + thirteen + "...\"'");
  // Exactly 40 bytes is not cut.
  const std::string forty(40, 'b');
  EXPECT_EQ(errorOf("sphere { " + forty + "; }"), "t.cfg:1:10: unknown material '" + forty + "'");
}

// ---------------------------------------------------------------- includes

TEST_F(ParserFiles, IncludeResolvesRelativeToTheIncludingFile) {
  write("sub/mats.cfg", "#include \"more/inner.cfg\"\nmaterial outer { texture = image { file = \"../img/x.png\"; } }\n");
  write("sub/more/inner.cfg", "material inner { texture = image {\n  file = \"tex.png\"; } }\n");
  std::string main = write("main.cfg", "#include \"sub/mats.cfg\"\nsphere { outer; }\nplane { inner; }\n");
  Scene s = parseSceneFile(main);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "inner");
  EXPECT_EQ(s.materials[0].texture.imagePath, (dir_ / "sub/more/tex.png").lexically_normal().string());
  EXPECT_EQ(s.materials[0].texture.loc.file, path("sub/more/inner.cfg"));
  EXPECT_EQ(s.materials[0].texture.loc.line, 2);
  EXPECT_EQ(s.materials[0].texture.loc.column, 10);
  EXPECT_EQ(s.materials[1].texture.imagePath, (dir_ / "img/x.png").lexically_normal().string());
  EXPECT_EQ(s.spheres[0].material, 1);
  EXPECT_EQ(s.planes[0].material, 0);
}

TEST_F(ParserFiles, AFileWithNoObjectIsAnError) {
  const std::string message = ":1:1: nothing to render: the scene has no sphere or plane";
  write("empty.cfg", "");
  EXPECT_EQ(fileErrorOf(path("empty.cfg")), path("empty.cfg") + message);
  write("library.cfg", "material m { diffuse = (1, 0, 0); }\nlight { position = (0, 5, 0); }\n");
  EXPECT_EQ(fileErrorOf(path("library.cfg")), path("library.cfg") + message);
  write("plane.cfg", "plane { normal = (0, 1, 0); distance = 0; }\n");
  EXPECT_EQ(parseSceneFile(path("plane.cfg")).planes.size(), 1u);
}

TEST_F(ParserFiles, IncludeNotFound) {
  std::string main = write("main.cfg", "// materials\n  #include \"missing.cfg\"\n");
  const std::string relative = ": an #include is relative to the including file's directory (" + dir_.string() + ")";
  EXPECT_EQ(fileErrorOf(main), main + ":2:3: cannot open included file '" + path("missing.cfg") + "'" + relative);
  // The course's materials file: where its copy is.
  std::string course = write("course.cfg", "#include \"texture_include.cfg\"\n");
  EXPECT_EQ(fileErrorOf(course), course + ":1:1: cannot open included file '" + path("texture_include.cfg") + "'" +
                                     relative + "; the course's materials are scenes/texture_include.cfg in raytex's "
                                     "source tree: copy it beside the scene or #include its path");
  // A directory is not a file either (it exists: no hint).
  fs::create_directories(dir_ / "adir");
  std::string d = write("d.cfg", "#include \"adir\"\n");
  EXPECT_EQ(fileErrorOf(d), d + ":1:1: cannot open included file '" + path("adir") + "'");
}

TEST_F(ParserFiles, IncludeCycleAToBToA) {
  std::string a = write("a.cfg", "#include \"b.cfg\"\n");
  std::string b = write("b.cfg", "material m { }\n\n  #include \"a.cfg\"\n");
  EXPECT_EQ(fileErrorOf(a), b + ":3:3: cyclic #include of '" + a + "' (" + a + " -> " + b + " -> " + a + ")");
}

TEST_F(ParserFiles, SelfInclude) {
  std::string s = write("self.cfg", "#include \"self.cfg\"\n");
  EXPECT_EQ(fileErrorOf(s), s + ":1:1: cyclic #include of '" + s + "' (" + s + " -> " + s + ")");
  // Also through a different spelling of the same file.
  std::string t = write("sub/t.cfg", "#include \"../sub/./t.cfg\"\n");
  EXPECT_EQ(fileErrorOf(t), t + ":1:1: cyclic #include of '" + path("sub/../sub/./t.cfg") + "' (" + t + " -> " +
                                path("sub/../sub/./t.cfg") + ")");
}

TEST_F(ParserFiles, IncludeDepthLimit) {
  // f0 includes f1 ... f(n-1) includes fn. 16 levels of nesting are fine; 17 are not.
  auto chain = [&](const std::string& prefix, int n) {
    for (int i = 0; i < n; ++i)
      write(prefix + std::to_string(i) + ".cfg", "#include \"" + prefix + std::to_string(i + 1) + ".cfg\"\n");
    write(prefix + std::to_string(n) + ".cfg", "material deep { }\nsphere { deep; }\n");
    return path(prefix + "0.cfg");
  };
  Scene ok = parseSceneFile(chain("ok", 16));
  ASSERT_EQ(ok.materials.size(), 1u);
  EXPECT_EQ(ok.materials[0].loc.file, path("ok16.cfg"));
  EXPECT_EQ(fileErrorOf(chain("bad", 17)), path("bad16.cfg") + ":1:1: #include nested more than 16 levels deep");
}

TEST_F(ParserFiles, ErrorsInsideAnIncludedFileReferToThatFile) {
  write("inc/mats.cfg", "material m {\n  difuse = (1, 1, 1);\n}\n");
  std::string main = write("main.cfg", "#include \"inc/mats.cfg\"\n");
  EXPECT_EQ(fileErrorOf(main), path("inc/mats.cfg") + ":2:3: unknown key 'difuse' in material 'm' (did you mean 'diffuse'?)");
  write("inc/dup.cfg", "material m { }\n");
  std::string twice = write("twice.cfg", "#include \"inc/dup.cfg\"\n#include \"inc/dup.cfg\"\n");
  EXPECT_EQ(fileErrorOf(twice),
            path("inc/dup.cfg") + ":1:10: duplicate material 'm' (first defined at " + path("inc/dup.cfg") + ":1:10)");
}

TEST_F(ParserFiles, AbsoluteIncludePath) {
  std::string main = write("main.cfg", "#include \"" + kSourceDir + "/scenes/texture_include.cfg\"\nsphere { aWood; }\n");
  Scene s = parseSceneFile(main);
  EXPECT_EQ(s.materials.size(), 8u);
  EXPECT_EQ(s.materials[size_t(s.spheres[0].material)].name, "aWood");
}

// ---------------------------------------------------------------- files that are not scenes

// An included file that is not a scene is refused at the #include, quoting none of its content.
TEST_F(ParserFiles, IncludedFilesThatAreNotScenesAreNotQuoted) {
  const std::string secret = "ghp_S3cr3tT0kenValue0123456789";
  const std::pair<const char*, std::string> files[] = {
      {"token.txt", secret + "\n"},
      {"shadow", "root:$y$j9T$" + secret + ":19700:0:99999:7:::\n"},
      {"maps", "55d0c0a00000-55d0c0a21000 r--p 00000000 08:01 1234567 /usr/bin/" + secret + "\n"},
      {"binary", std::string("\x7f" "ELF\x02\x01\x01\0", 8) + secret},
      {"string", "\"" + secret + "\"\n"},
      {"directive", "#" + secret + "\n"},
  };
  for (const auto& [name, content] : files) {
    write(name, content);
    std::string main = write("main.cfg", "material m { }\n  #include \"" + std::string(name) + "\"\n");
    std::string message = fileErrorOf(main);
    EXPECT_EQ(message, main + ":2:3: '" + path(name) + "' is not a scene file");
    EXPECT_EQ(message.find("S3cr3t"), std::string::npos) << message;
  }
}

TEST_F(ParserFiles, ScenesAreKnownByTheirFirstToken) {
  // Empty, comment-only, a near miss of a keyword, and #include all count as scenes.
  write("empty.cfg", "");
  write("comments.cfg", "// nothing\n/* at all */\n");
  write("spher.cfg", "\n  spher { }\n");
  write("inc.cfg", "#include \"empty.cfg\"\n");
  EXPECT_EQ(parseSceneFile(write("a.cfg", "#include \"empty.cfg\"\n#include \"comments.cfg\"\n"
                                          "#include \"inc.cfg\"\nsphere { }\n"))
                .spheres.size(),
            1u);
  EXPECT_EQ(fileErrorOf(write("b.cfg", "#include \"spher.cfg\"\n")),
            path("spher.cfg") + ":2:3: unknown top-level keyword 'spher' (did you mean 'sphere'?)");
  // The scene named on the command line follows the same rule.
  std::string token = write("token.cfg", "hunter2isMyPassword\n");
  EXPECT_EQ(fileErrorOf(token), token + ":1:1: '" + token + "' is not a scene file");
  std::string garbage = write("garbage.cfg", std::string("\xff\xfe\x00secret", 9));
  EXPECT_EQ(fileErrorOf(garbage), garbage + ":1:1: '" + garbage + "' is not a scene file");
  EXPECT_EQ(fileErrorOf(path("empty.cfg")), path("empty.cfg") + ":1:1: nothing to render: the scene has no sphere or plane");
}

// A path longer than PATH_MAX is refused where it is written, and the message does not quote it.
TEST_F(ParserFiles, OverlongPathsAreRefusedWithoutQuotingThem) {
  const std::string longName(5000, 'x');
  std::string inc = write("inc.cfg", "#include \"" + longName + "\"\n");
  EXPECT_EQ(fileErrorOf(inc), inc + ":1:10: file path is longer than 4096 bytes");
  std::string img = write("img.cfg", "material m { texture = image { file = \"" + longName + ".png\"; } }\nsphere { m; }\n");
  EXPECT_EQ(fileErrorOf(img), img + ":1:39: file path is longer than 4096 bytes");
}

// ---------------------------------------------------------------- --allow-read

class ParserAllowRead : public ParserFiles {
 protected:
  void SetUp() override {
    ParserFiles::SetUp();
    write("allowed/mats.cfg", "material m { }\n");
    write("allowed/sub/more.cfg", "material n { }\n");
    write("other/secret.cfg", "material s { }\n");
    write("other2/mats.cfg", "material o { }\n");
  }
  // The error of parsing `text` as scene allowed/s.cfg under --allow-read dirs.
  std::string errorUnder(const std::string& text, std::vector<std::string> dirs) {
    std::string scene = write("allowed/s.cfg", text + "sphere { }\n");
    try {
      parseSceneFile(scene, ReadPolicy{dirs});
    } catch (const SceneError& e) {
      return e.what();
    }
    return "<no error>";
  }
  std::string outside(const std::string& line, const std::string& col, const std::string& p) {
    return path("allowed/s.cfg") + ":" + line + ":" + col + ": '" + p + "' is outside the directories --allow-read allows";
  }
};

TEST_F(ParserAllowRead, IncludesInsideTheTreeAreRead) {
  EXPECT_EQ(errorUnder("#include \"mats.cfg\"\n#include \"sub/more.cfg\"\n", {path("allowed")}), "<no error>");
  EXPECT_EQ(errorUnder("#include \"sub/../mats.cfg\"\n", {path("allowed") + "/"}), "<no error>");
}

TEST_F(ParserAllowRead, DotDotEscapesAreRefused) {
  EXPECT_EQ(errorUnder("#include \"../other/secret.cfg\"\n", {path("allowed")}),
            outside("1", "10", path("allowed/../other/secret.cfg")));
  // Refused the same way whether or not the file exists.
  EXPECT_EQ(errorUnder("#include \"../other/none.cfg\"\n", {path("allowed")}),
            outside("1", "10", path("allowed/../other/none.cfg")));
  // A sibling whose name starts with the allowed one is not inside it.
  write("allowed2/x.cfg", "material x { }\n");
  EXPECT_EQ(errorUnder("#include \"../allowed2/x.cfg\"\n", {path("allowed")}),
            outside("1", "10", path("allowed/../allowed2/x.cfg")));
}

TEST_F(ParserAllowRead, SymlinkEscapesAreRefused) {
  fs::create_symlink(dir_ / "other/secret.cfg", dir_ / "allowed/link.cfg");
  fs::create_directory_symlink(dir_ / "other", dir_ / "allowed/linkdir");
  EXPECT_EQ(errorUnder("#include \"link.cfg\"\n", {path("allowed")}), outside("1", "10", path("allowed/link.cfg")));
  EXPECT_EQ(errorUnder("\n#include \"linkdir/secret.cfg\"\n", {path("allowed")}),
            outside("2", "10", path("allowed/linkdir/secret.cfg")));
  // A symlink inside the tree to a file inside the tree is fine.
  fs::create_symlink(dir_ / "allowed/mats.cfg", dir_ / "allowed/inner.cfg");
  EXPECT_EQ(errorUnder("#include \"inner.cfg\"\n", {path("allowed")}), "<no error>");
}

TEST_F(ParserAllowRead, ImagesOutsideAreRefused) {
  EXPECT_EQ(errorUnder("material i { texture = image { file = \"../other/x.png\"; } }\n", {path("allowed")}),
            outside("1", "39", path("other/x.png")));
  EXPECT_EQ(errorUnder("material i { texture = image { file = \"x.png\"; } }\n", {path("allowed")}), "<no error>");
  // Without --allow-read, nothing is confined.
  EXPECT_EQ(errorUnder("material i { texture = image { file = \"../other/x.png\"; } }\n"
                       "#include \"../other/secret.cfg\"\n",
                       {}),
            "<no error>");
}

TEST_F(ParserAllowRead, TwoTreesAndRelativeDirectories) {
  EXPECT_EQ(errorUnder("#include \"../other2/mats.cfg\"\n#include \"mats.cfg\"\n", {path("allowed"), path("other2")}),
            "<no error>");
  EXPECT_EQ(errorUnder("#include \"../other2/mats.cfg\"\n#include \"../other/secret.cfg\"\n",
                       {path("allowed"), path("other2")}),
            outside("2", "10", path("allowed/../other/secret.cfg")));
  // Relative to the working directory.
  fs::path cwd = fs::current_path();
  fs::current_path(dir_ / "other2");
  std::string ok = errorUnder("#include \"mats.cfg\"\n", {"../allowed"});
  std::string bad = errorUnder("#include \"../other/secret.cfg\"\n", {"../allowed", "."});
  std::string good = errorUnder("#include \"../other2/mats.cfg\"\n", {"../allowed", "."});
  fs::current_path(cwd);
  EXPECT_EQ(ok, "<no error>");
  EXPECT_EQ(bad, outside("1", "10", path("allowed/../other/secret.cfg")));
  EXPECT_EQ(good, "<no error>");
}

// ---------------------------------------------------------------- robustness

TEST(ParserRobustness, TruncatedAndMutatedInputsOnlyEverThrowSceneError) {
  const std::string original = readFile(kTexturesCfg);
  ASSERT_GT(original.size(), 100u);
  std::mt19937 rng(12345);
  const std::string interesting = "{}();,=\"/*#-+.eE0123456789aZ_ \n\t\r";
  auto pick = [&](size_t n) { return size_t(std::uniform_int_distribution<size_t>(0, n - 1)(rng)); };

  std::vector<std::string> inputs;
  size_t step = std::max<size_t>(1, original.size() / 700);
  for (size_t n = 0; n < original.size(); n += step) inputs.push_back(original.substr(0, n));
  while (inputs.size() < 2000) {
    std::string t = original;
    int edits = 1 + int(pick(4));
    for (int e = 0; e < edits && !t.empty(); ++e) {
      size_t at = pick(t.size());
      char c = pick(3) == 0 ? char(pick(256)) : interesting[pick(interesting.size())];
      switch (pick(3)) {
        case 0: t[at] = c; break;
        case 1: t.insert(t.begin() + long(at), c); break;
        default: t.erase(at, 1 + pick(8)); break;
      }
    }
    inputs.push_back(t);
  }

  auto start = std::chrono::steady_clock::now();
  int ok = 0, errors = 0;
  for (const std::string& text : inputs) {
    try {
      Scene s = parseSceneText(text, kTexturesCfg);
      ++ok;
      for (const Sphere& sp : s.spheres) EXPECT_TRUE(sp.material >= -1 && sp.material < int(s.materials.size()));
      for (const Plane& pl : s.planes) EXPECT_TRUE(pl.material >= -1 && pl.material < int(s.materials.size()));
    } catch (const SceneError& e) {
      ++errors;
      EXPECT_GE(e.loc.line, 1) << e.what();
      EXPECT_GE(e.loc.column, 1) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(e.loc.file + ":", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << " for input:\n" << text;
    } catch (...) {
      ADD_FAILURE() << "unexpected non-std exception for input:\n" << text;
    }
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(ok + errors, int(inputs.size()));
  EXPECT_GT(ok, 0);
  EXPECT_GT(errors, 0);
  EXPECT_LT(seconds, 30.0);
}

// --- render settings -------------------------------------------------------------

TEST(ParserRender, BlockSetsSizeSamplesAndFilter) {
  Scene s = parseSceneText("render {\n  width = 320; height = 200;\n  spp = 16;\n  filter = box;\n}\n", "r.cfg");
  EXPECT_EQ(s.render.width, 320);
  EXPECT_EQ(s.render.height, 200);
  EXPECT_EQ(s.render.samplesPerPixel, 16);
  EXPECT_EQ(s.render.filter, TextureFilter::Box);
  EXPECT_EQ(parseSceneText("render { filter = coverage; }\n", "c.cfg").render.filter, TextureFilter::Coverage);
  EXPECT_FALSE(s.render.imageFilter.has_value());
  EXPECT_EQ(parseSceneText("render { filter = box; image_filter = ewa; }\n", "i.cfg").render.imageFilter, ImageFilter::Ewa);
  Scene none = parseSceneText("", "e.cfg");
  EXPECT_FALSE(none.render.width.has_value());
  EXPECT_FALSE(none.render.samplesPerPixel.has_value());
  EXPECT_FALSE(none.render.filter.has_value());
}

TEST(ParserRender, Errors) {
  EXPECT_EQ(errorOf("render { spp = 5; }\n"), "t.cfg:1:16: spp must be a square number (1, 4, 9, 16, ...), got 5");
  EXPECT_EQ(errorOf("render { width = 0; }\n"), "t.cfg:1:18: width must be a whole number from 1 to 16384, got 0");
  EXPECT_EQ(errorOf("render { height = 2.5; }\n"),
            "t.cfg:1:19: height must be a whole number from 1 to 16384, got 2.5");
  EXPECT_EQ(errorOf("render { filter = bilinear; }\n"), "t.cfg:1:19: filter must be point, box or coverage, got 'bilinear'");
  EXPECT_EQ(errorOf("render { image_filter = box; }\n"),
            "t.cfg:1:25: image_filter must be anisotropic, trilinear, bilinear, ewa or stochastic, got 'box'");
  EXPECT_EQ(errorOf("render { samples = 4; }\n"), "t.cfg:1:10: unknown key 'samples' in render");
  EXPECT_EQ(errorOf("render { }\nrender { }\n"), "t.cfg:2:1: duplicate render (first defined at t.cfg:1:1)");
}

// ---------------------------------------------------------------- texture placement

TEST(ParserPlacement, SpheresAndPlanesTakeEveryPlacementKey) {
  Scene s = parseSceneText(
      "material m { texture = marble; }\n"
      "sphere { tex_rotate = (0, 180, -10.5); tex_scale = 0.5; tex_offset = (1, 2, 3); m; }\n"
      "plane { m; tex_offset = (-0.25, 0, 7); tex_rotate = (30, 0, 0); }\n"
      "sphere { }\n",
      "t.cfg");
  expectVec(s.spheres[0].placement.rotate, 0, 180, -10.5);
  EXPECT_EQ(s.spheres[0].placement.scale, 0.5);
  expectVec(s.spheres[0].placement.offset, 1, 2, 3);
  expectVec(s.planes[0].placement.rotate, 30, 0, 0);
  EXPECT_EQ(s.planes[0].placement.scale, 1.0);
  expectVec(s.planes[0].placement.offset, -0.25, 0, 7);
  expectVec(s.spheres[1].placement.rotate, 0, 0, 0);  // the defaults: no placement
  EXPECT_EQ(s.spheres[1].placement.scale, 1.0);
  expectVec(s.spheres[1].placement.offset, 0, 0, 0);
}

TEST(ParserPlacement, BadPlacementsSayWhere) {
  EXPECT_EQ(errorOf("sphere { tex_scale = -1; }"), "t.cfg:1:22: tex_scale must be > 0, got -1");
  EXPECT_EQ(errorOf("plane { tex_rotate = (0, 0, 361); }"), "t.cfg:1:22: tex_rotate angles must be from -360 to 360 degrees");
  EXPECT_EQ(errorOf("sphere { tex_rotate = (1, 2); }"), "t.cfg:1:23: expected 3 numbers, got 2");
  EXPECT_EQ(errorOf("sphere { tex_offset = (0, 0, 0); tex_offset = (1, 0, 0); }"),
            "t.cfg:1:34: duplicate key 'tex_offset' in sphere (first given at t.cfg:1:10)");
  // A 2D kind reads (u, v) only.
  EXPECT_EQ(errorOf("material m { texture = checker; }\nplane { tex_offset = (0, 0, 1); m; }"),
            "t.cfg:2:22: tex_offset's third component must be 0 on a checker texture (it offsets (u, v) only)");
  EXPECT_EQ(errorOf("material m { texture = checker; }\nplane { tex_offset = (0.5, 0.5, 0); m; }"), "<no error>");
  // Placement belongs to the object, not to its material or texture.
  EXPECT_EQ(errorOf("material m { tex_scale = 2; }"),
            "t.cfg:1:14: 'tex_scale' is not a key of material 'm': texture placement belongs in the sphere or plane block");
  EXPECT_EQ(errorOf("material m { texture = wood { tex_offset = (1, 0, 0); } }"),
            "t.cfg:1:31: 'tex_offset' is not a key of wood texture: texture placement belongs in the sphere or plane "
            "block");
  EXPECT_EQ(errorOf("material tex_rotate { }"),
            "t.cfg:1:10: 'tex_rotate' is a reserved word and cannot name a material");
}
