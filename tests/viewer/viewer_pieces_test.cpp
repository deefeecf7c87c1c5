// The viewer's pieces that need no window or device: what Tab selects and what 1-8 and M put on
// it (host/viewer/selection.cpp), the magnifier's readout, the camera block C prints
// (host/viewer/camera_block.cpp), the overlays drawn over the window's pixels (host/viewer/overlay.cpp)
// and the key table (host/viewer/input.cpp) against docs/viewer.md.
#include "camera_block.h"
#include "common.h"
#include "input.h"
#include "overlay.h"
#include "parser.h"
#include "selection.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

const char* const kCourse[] = {"aSolidChecker", "aNoise",       "aMarble",  "aWood",
                               "anImage",       "aTurbulence", "aDturbulence", "aChecker"};

Scene courseScene() { return parseSceneFile(kSourceDir + "/scenes/textures.cfg"); }

int material(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return int(i);
  return -1;
}

}  // namespace

TEST(Selection, TheCursorSelectsWhatItsPixelShows) {
  const Scene scene = courseScene();
  // 160 x 120 view of the course scene: the sphere in the middle, the floor below, the sky above.
  const Selection sphere = objectAt(scene, 160, 120, 80.5, 50.5);
  EXPECT_EQ(sphere.kind, HIT_SPHERE);
  EXPECT_EQ(sphere.index, 0);
  EXPECT_EQ(objectAt(scene, 160, 120, 80.5, 110.5).kind, HIT_PLANE);
  EXPECT_EQ(objectAt(scene, 160, 120, 80.5, 1.5).kind, HIT_NONE);
  EXPECT_EQ(selectionName(scene, sphere), "sphere 1 (textures.cfg:29)");
  EXPECT_EQ(selectionName(scene, Selection{}), "nothing");
}

TEST(Selection, MaterialsGoOnTheSelectionOrEverySphere) {
  Scene scene = parseSceneText(
      "material a { }\nmaterial b { }\nsphere { a; }\nsphere { center = (3, 0, 0); a; }\nplane { a; }\n", "s.cfg");
  applyMaterial(scene, Selection{HIT_SPHERE, 1}, 1);
  EXPECT_EQ(scene.spheres[0].material, 0);
  EXPECT_EQ(scene.spheres[1].material, 1);
  applyMaterial(scene, Selection{HIT_PLANE, 0}, 1);
  EXPECT_EQ(scene.planes[0].material, 1);
  applyMaterial(scene, Selection{}, -1);
  EXPECT_EQ(scene.spheres[0].material, -1);
  EXPECT_EQ(scene.spheres[1].material, -1);
  EXPECT_EQ(scene.planes[0].material, 1);
  EXPECT_EQ(selectedMaterial(scene, Selection{HIT_PLANE, 0}), 1);
  EXPECT_EQ(selectedMaterial(scene, Selection{}), -1);
}

TEST(Selection, MCyclesTheScenesOwnMaterialsThenTheCourses) {
  Scene scene = parseSceneText("#include \"texture_include.cfg\"\nmaterial mine { }\nmaterial other { }\nsphere { }\n",
                               kSourceDir + "/scenes/m.cfg");
  const int mine = material(scene, "mine"), other = material(scene, "other");
  EXPECT_EQ(nextMaterial(scene, -1, kCourse, 8), mine);
  EXPECT_EQ(nextMaterial(scene, mine, kCourse, 8), other);
  EXPECT_EQ(nextMaterial(scene, other, kCourse, 8), material(scene, "aSolidChecker"));
  EXPECT_EQ(nextMaterial(scene, material(scene, "aMarble"), kCourse, 8), material(scene, "aWood"));
  EXPECT_EQ(nextMaterial(scene, material(scene, "aChecker"), kCourse, 8), mine);
  EXPECT_EQ(nextMaterial(parseSceneText("sphere { }\n", "n.cfg"), -1, kCourse, 8), -1);
}

TEST(Selection, TheReadoutNamesUvAndTheImageTexel) {
  Scene scene = courseScene();
  scene.spheres[0].material = material(scene, "anImage");
  const ReferenceHit hit = hitAt(scene, 160, 120, 80.5, 50.5);
  ASSERT_EQ(hit.kind, HIT_SPHERE);
  SceneImage earth;
  earth.path = scene.materials[size_t(material(scene, "anImage"))].texture.imagePath;
  earth.header.width = 2048;
  earth.header.height = 1024;
  char expected[96];
  snprintf(expected, sizeof(expected), "sphere 1 uv (%.4f, %.4f) texel (%d, %d) of earth.jpg", hit.tc.uv.x, hit.tc.uv.y,
           int(std::floor(hit.tc.image.x * 2048)), int(std::floor(hit.tc.image.y * 1024)));
  EXPECT_EQ(pointReadout(scene, hit, {earth}), expected);
  scene.spheres[0].material = material(scene, "aMarble");
  EXPECT_NE(pointReadout(scene, hit, {}).find(" solid ("), std::string::npos);
  EXPECT_EQ(pointReadout(scene, hitAt(scene, 160, 120, 80.5, 1.5), {}), "background");
}

TEST(CameraBlock, PrintedBlockParsesToThePrintedCamera) {
  Camera camera;
  camera.eye = {0.1 + 1e-12, -3.0000000004, 12.345678912345};
  camera.lookat = {0.0, -0.5, 1.0 / 3.0};
  camera.up = {0.0, 1.0, 0.0};
  camera.fovY = 35.000000001;
  const Camera printed = printedCamera(camera);
  EXPECT_EQ(printedCamera(printed).eye, printed.eye);  // printing again changes nothing
  const Scene scene = parseSceneText(cameraBlock(camera) + "sphere { }\n", "c.cfg");
  EXPECT_EQ(scene.camera.eye, printed.eye);
  EXPECT_EQ(scene.camera.lookat, printed.lookat);
  EXPECT_EQ(scene.camera.up, printed.up);
  EXPECT_EQ(scene.camera.fovY, printed.fovY);
  EXPECT_NE(printed.eye, camera.eye);  // the digits past %.9g are gone
  EXPECT_EQ(cameraBlock(camera).rfind("camera {\n    eye = (0.1, -3, 12.3456789);\n", 0), 0u) << cameraBlock(camera);
}

TEST(Overlay, TheHelpBoxDarkensItsCornerAndLeavesTheRest) {
  std::vector<uint32_t> pixels(200 * 100, 0xFF808080u);
  OverlayPixels image{pixels.data(), 200, 100, false};
  drawTextBox(image, {"H help"});
  EXPECT_EQ(pixels[199 + 99 * 200], 0xFF808080u);  // far corner untouched
  int white = 0, dark = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 60; ++x) {
      white += pixels[size_t(y) * 200 + size_t(x)] == 0xFFFFFFFFu;
      dark += pixels[size_t(y) * 200 + size_t(x)] == 0xFF202020u;
    }
  EXPECT_GT(white, 20);  // the text
  EXPECT_GT(dark, 500);  // the box around it
}

TEST(Overlay, TheMagnifierRepeatsEachPixelZoomTimes) {
  std::vector<uint32_t> pixels(300 * 300);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = 0xFF000000u | uint32_t(i % 300) | uint32_t(i / 300) << 8;
  std::vector<uint32_t> before = pixels;
  OverlayPixels image{pixels.data(), 300, 300, false};
  drawMagnifier(image, 50, 60);
  // The square sits to the cursor's lower right: its pixel (i, j) shows the source pixel
  // (50 - 8 + i / 8, 60 - 8 + j / 8).
  const int left = 50 + 16, top = 60 + 16, half = kMagnifierSource / 2;
  for (int j = 1; j < kMagnifierSource * kMagnifierZoom - 1; j += 7)
    for (int i = 1; i < kMagnifierSource * kMagnifierZoom - 1; i += 7) {
      if (std::abs(i / kMagnifierZoom - half) <= 1 && std::abs(j / kMagnifierZoom - half) <= 1) continue;  // outline
      const uint32_t source = before[size_t(60 - half + j / kMagnifierZoom) * 300 + size_t(50 - half + i / kMagnifierZoom)];
      ASSERT_EQ(pixels[size_t(top + j) * 300 + size_t(left + i)], source) << i << ", " << j;
    }
  EXPECT_EQ(pixels[10 * 300 + 10], before[10 * 300 + 10]);  // away from it, unchanged
}

TEST(Overlay, TheUvPassIsRedUGreenV) {
  std::vector<uint32_t> pixels(2);
  const float uv[8] = {0.5f, 1.0f, 0.0f, 1.0f, 2.0f, -1.0f, NAN, 1.0f};
  OverlayPixels rgba{pixels.data(), 2, 1, false};
  drawUvPass(rgba, uv);
  EXPECT_EQ(pixels[0], 0xFF00FF80u);  // R 128, G 255, B 0 in R, G, B, A byte order
  EXPECT_EQ(pixels[1], 0xFF0000FFu);  // clamped; NaN as 0
  OverlayPixels bgra{pixels.data(), 2, 1, true};
  drawUvPass(bgra, uv);
  EXPECT_EQ(pixels[0], 0xFF80FF00u);
}

TEST(Overlay, TheSplitTakesTheRightImageFromItsColumnWithALine) {
  std::vector<uint32_t> left(4 * 2, 0xFF000001u), right(4 * 2, 0xFF000002u);
  OverlayPixels image{left.data(), 4, 2, false};
  drawSplit(image, right.data(), 2);
  const std::vector<uint32_t> expected = {0xFF000001u, 0xFF000001u, 0xFFFFFFFFu, 0xFF000002u,
                                          0xFF000001u, 0xFF000001u, 0xFFFFFFFFu, 0xFF000002u};
  EXPECT_EQ(left, expected);
  std::vector<uint32_t> edge(4, 0xFF000001u);
  OverlayPixels atEdge{edge.data(), 4, 1, false};
  drawSplit(atEdge, right.data(), 0);  // at an edge: no line, all the right image
  EXPECT_EQ(edge, std::vector<uint32_t>(4, 0xFF000002u));
}

TEST(Overlay, HelpTooWideForTheWindowWrapsItsDescriptions) {
  const std::string line = "K\tone two three four five six seven eight nine ten eleven twelve";
  auto lowestWhiteRow = [&](int width) {
    std::vector<uint32_t> pixels(size_t(width) * 200, 0xFF808080u);
    OverlayPixels image{pixels.data(), width, 200, false};
    drawTextBox(image, {line});
    int lowest = -1;
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < width; ++x)
        if (pixels[size_t(y) * size_t(width) + size_t(x)] == 0xFFFFFFFFu) lowest = y;
    return lowest;
  };
  const int wide = lowestWhiteRow(1000), narrow = lowestWhiteRow(150);
  EXPECT_GT(wide, 0);
  EXPECT_GT(narrow, wide + 24);  // at least two more lines of 12 pixels
}

// docs/viewer.md's key table lists the rows of the viewer's key table (host/viewer/input.cpp),
// in its order; H draws one line a row, the keys and what they do apart.
TEST(Input, TheDocsListTheKeyTable) {
  const std::string doc = readFile(kSourceDir + "/docs/viewer.md");
  const size_t begin = doc.find("| key | action |\n|---|---|\n");
  ASSERT_NE(begin, std::string::npos) << "docs/viewer.md lacks its key table";
  std::vector<std::string> documented;
  for (size_t at = doc.find('\n', doc.find('\n', begin) + 1) + 1; at < doc.size() && doc[at] == '|';
       at = doc.find('\n', at) + 1)
    documented.push_back(doc.substr(at + 2, doc.find(" |", at + 1) - at - 2));
  std::vector<std::string> rows;
  for (const KeyHelp& row : keyHelp()) rows.push_back(row.keys);
  EXPECT_EQ(documented, rows);
  const std::vector<std::string> lines = keyHelpLines();
  ASSERT_EQ(lines.size(), rows.size());
  for (size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(lines[i].substr(0, lines[i].find('\t')), rows[i]);
}
