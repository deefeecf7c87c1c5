#include "input.h"

#include "camera_block.h"
#include "viewer_state.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace {

ViewerState& stateOf(GLFWwindow* window) { return *static_cast<ViewerState*>(glfwGetWindowUserPointer(window)); }

// The cursor's position in the image's pixels (the framebuffer's, which may differ from the
// window's coordinates).
void cursorPixel(GLFWwindow* window, double x, double y, ViewerState& state) {
  int windowW = 0, windowH = 0, pixelsW = 0, pixelsH = 0;
  glfwGetWindowSize(window, &windowW, &windowH);
  glfwGetFramebufferSize(window, &pixelsW, &pixelsH);
  state.cursorX = windowW > 0 ? x * pixelsW / windowW : x;
  state.cursorY = windowH > 0 ? y * pixelsH / windowH : y;
}

// V's split at the cursor's column.
void moveSplit(GLFWwindow* window, ViewerState& state) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  state.splitAt = std::clamp(state.cursorX / std::max(width, 1), 0.0, 1.0);
  state.refresh = true;
}

// Material `index` on the selection (or every sphere), shown on the next frame.
void switchMaterial(ViewerState& state, int index) {
  applyMaterial(state.scene, state.selection, index);
  state.cameraMoved = true;
  state.switchedAt = Clock::now();
}

// The handlers of the key table's rows: the window, the state, the key and its GLFW action.
using KeyHandler = void (*)(GLFWwindow*, ViewerState&, int key, int action);

void selectUnderCursor(GLFWwindow* window, ViewerState& state, int, int) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  state.selection = objectAt(state.scene, std::max(width, 1), std::max(height, 1), state.cursorX, state.cursorY);
  say(state, state.selection.kind ? "selected " + selectionName(state.scene, state.selection) : "nothing selected");
}

void courseMaterial(GLFWwindow*, ViewerState& state, int key, int) {
  const char* name = kCourseMaterials[key - GLFW_KEY_1];
  const int index = materialIndex(state.scene, name);
  if (index < 0) say(state, std::string(name) + " is not defined by this scene");
  else switchMaterial(state, index);
}

void nextObjectMaterial(GLFWwindow*, ViewerState& state, int, int) {
  const int next =
      nextMaterial(state.scene, selectedMaterial(state.scene, state.selection), kCourseMaterials, kCourseMaterialCount);
  if (next < 0) say(state, "the scene defines no material");
  else switchMaterial(state, next);
}

// P: the next course material the scene defines, on every plane.
void nextPlaneMaterial(GLFWwindow*, ViewerState& state, int, int) {
  for (size_t step = 1; step <= kCourseMaterialCount; ++step) {
    const int next = int((state.planeMaterial + step + kCourseMaterialCount) % kCourseMaterialCount);
    const int index = materialIndex(state.scene, kCourseMaterials[next]);
    if (index < 0) continue;
    state.planeMaterial = next;
    for (Plane& p : state.scene.planes) p.material = index;
    state.cameraMoved = true;
    state.switchedAt = Clock::now();
    return;
  }
}

constexpr double kOrbitStep = 5.0 * 3.14159265358979 / 180.0;  // radians a key press

void orbit(GLFWwindow*, ViewerState& state, int key, int) {
  const bool left = key == GLFW_KEY_LEFT || key == GLFW_KEY_A, right = key == GLFW_KEY_RIGHT || key == GLFW_KEY_D;
  const bool up = key == GLFW_KEY_UP || key == GLFW_KEY_W;
  if (left || right) moveCamera(state, left ? -kOrbitStep : kOrbitStep, 0.0, 1.0);
  else moveCamera(state, 0.0, up ? kOrbitStep : -kOrbitStep, 1.0);
}

void zoom(GLFWwindow*, ViewerState& state, int key, int) {
  const bool in = key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD || key == GLFW_KEY_PAGE_UP;
  moveCamera(state, 0.0, 0.0, in ? 0.9 : 1.0 / 0.9);
}

void homeCamera(GLFWwindow*, ViewerState& state, int, int) {
  state.scene.camera = state.orbit.home;
  state.orbit = orbitOf(state.orbit.home);
  state.cameraMoved = true;
}

void printCamera(GLFWwindow*, ViewerState& state, int, int) {
  printf("%s", cameraBlock(state.scene.camera).c_str());
  fflush(stdout);
  say(state, "camera printed to the terminal");
}

// Z, held: the magnifier shows until the key is released.
void magnifier(GLFWwindow*, ViewerState& state, int, int action) {
  state.magnifier = action != GLFW_RELEASE;
  state.refresh = true;
}

void uvPass(GLFWwindow*, ViewerState& state, int, int) {
  state.uvPass = !state.uvPass;
  state.refresh = true;
}

void toggleSplit(GLFWwindow*, ViewerState& state, int, int) {
  state.split = !state.split;
  state.cameraMoved = true;  // both methods start again
}

void splitMethod(GLFWwindow*, ViewerState& state, int, int) {
  if (!state.split) return;
  state.splitFilter = nextFilter(state.splitFilter, state.filter);
  state.cameraMoved = true;
}

void stepSplit(GLFWwindow*, ViewerState& state, int key, int) {
  if (!state.split) return;
  state.splitAt = std::clamp(state.splitAt + (key == GLFW_KEY_LEFT_BRACKET ? -1.0 : 1.0) / 32.0, 0.0, 1.0);
  state.refresh = true;
}

void help(GLFWwindow*, ViewerState& state, int, int) {
  state.help = !state.help;
  state.refresh = true;
}

void screenshot(GLFWwindow*, ViewerState& state, int, int) { state.screenshot = true; }

void quit(GLFWwindow* window, ViewerState&, int, int) { glfwSetWindowShouldClose(window, GLFW_TRUE); }

// When a row's handler runs: at the press only, again while the key repeats, or at the press
// and at the release.
enum class Fires { Press, Repeat, PressAndRelease };

struct KeyRow {
  KeyHelp help;
  std::initializer_list<int> keys;  // GLFW key codes
  Fires fires;
  KeyHandler handle;
};

// The key table, in the order H and the docs list it.
const KeyRow kKeys[] = {
    {{"Tab", "select the object under the cursor"}, {GLFW_KEY_TAB}, Fires::Press, selectUnderCursor},
    {{"1 - 8", "course material on the selection (or every sphere)"},
     {GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4, GLFW_KEY_5, GLFW_KEY_6, GLFW_KEY_7, GLFW_KEY_8},
     Fires::Press,
     courseMaterial},
    {{"M", "next material: the scene's own, then the course's"}, {GLFW_KEY_M}, Fires::Press, nextObjectMaterial},
    {{"P", "next course material on the planes"}, {GLFW_KEY_P}, Fires::Press, nextPlaneMaterial},
    {{"drag, arrows, WASD", "orbit"},
     {GLFW_KEY_LEFT, GLFW_KEY_RIGHT, GLFW_KEY_UP, GLFW_KEY_DOWN, GLFW_KEY_A, GLFW_KEY_D, GLFW_KEY_W, GLFW_KEY_S},
     Fires::Repeat,
     orbit},
    {{"scroll, + -, PgUp PgDn", "zoom"},
     {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD, GLFW_KEY_PAGE_UP, GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT, GLFW_KEY_PAGE_DOWN},
     Fires::Repeat,
     zoom},
    {{"R", "the scene file's camera"}, {GLFW_KEY_R}, Fires::Repeat, homeCamera},
    {{"C", "print the view as the scene file's camera block"}, {GLFW_KEY_C}, Fires::Press, printCamera},
    {{"Z (hold)", "magnifier; uv and texel in the title"}, {GLFW_KEY_Z}, Fires::PressAndRelease, magnifier},
    {{"U", "uv pass (red u, green v)"}, {GLFW_KEY_U}, Fires::Press, uvPass},
    {{"V", "split screen: the render's method | another"}, {GLFW_KEY_V}, Fires::Press, toggleSplit},
    {{"B", "the split's other method: point, box, coverage"}, {GLFW_KEY_B}, Fires::Press, splitMethod},
    {{"[ ], right drag", "move the split"}, {GLFW_KEY_LEFT_BRACKET, GLFW_KEY_RIGHT_BRACKET}, Fires::Press, stepSplit},
    {{"H", "this help"}, {GLFW_KEY_H}, Fires::Press, help},
    {{"F12", "write -o FILE once every sample is in"}, {GLFW_KEY_F12}, Fires::Press, screenshot},
    {{"Esc, Q", "quit"}, {GLFW_KEY_ESCAPE, GLFW_KEY_Q}, Fires::Press, quit},
};

const KeyRow* rowOf(int key) {
  for (const KeyRow& row : kKeys)
    if (std::find(row.keys.begin(), row.keys.end(), key) != row.keys.end()) return &row;
  return nullptr;
}

void onKey(GLFWwindow* window, int key, int, int action, int) {
  const KeyRow* row = rowOf(key);
  if (!row) return;
  const bool fires = action == GLFW_PRESS || (action == GLFW_REPEAT && row->fires == Fires::Repeat) ||
                     (action == GLFW_RELEASE && row->fires == Fires::PressAndRelease);
  if (fires) row->handle(window, stateOf(window), key, action);
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
  ViewerState& state = stateOf(window);
  if (button == GLFW_MOUSE_BUTTON_RIGHT) {
    state.splitDragging = action == GLFW_PRESS && state.split;
    if (state.splitDragging) moveSplit(window, state);
    return;
  }
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  state.dragging = action == GLFW_PRESS;
  glfwGetCursorPos(window, &state.lastX, &state.lastY);
}

void onCursor(GLFWwindow* window, double x, double y) {
  ViewerState& state = stateOf(window);
  if (state.dragging) moveCamera(state, -(x - state.lastX) * 0.01, (y - state.lastY) * 0.01, 1.0);
  state.lastX = x;
  state.lastY = y;
  cursorPixel(window, x, y, state);
  if (state.magnifier) state.refresh = true;
  if (state.splitDragging) moveSplit(window, state);
}

void onScroll(GLFWwindow* window, double, double yOffset) { moveCamera(stateOf(window), 0.0, 0.0, std::pow(0.9, yOffset)); }

}  // namespace

std::vector<KeyHelp> keyHelp() {
  std::vector<KeyHelp> rows;
  for (const KeyRow& row : kKeys) rows.push_back(row.help);
  return rows;
}

const std::vector<std::string>& keyHelpLines() {
  static const std::vector<std::string> lines = [] {
    std::vector<std::string> made;
    for (const KeyRow& row : kKeys) made.push_back(std::string(row.help.keys) + "\t" + row.help.does);
    return made;
  }();
  return lines;
}

void installInput(GLFWwindow* window, ViewerState* state) {
  glfwSetWindowUserPointer(window, state);
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { stateOf(w).refresh = true; });
}
