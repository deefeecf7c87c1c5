// The viewer's input: one table of keys, which drives both what each key does and the list that
// H shows over the image and `raytex --help` prints; and the mouse (drag orbits, scroll zooms,
// right-drag moves the split).
#pragma once

#include <string>
#include <vector>

struct GLFWwindow;
struct ViewerState;

// One row of the key table as people read it: the keys ("1 - 8", "Esc, Q") and what they do.
struct KeyHelp {
  const char* keys;
  const char* does;
};

// Every row of the key table, in its order (docs/viewer.md's table lists the same keys).
std::vector<KeyHelp> keyHelp();

// The rows as H draws them (every frame the help is on): the keys, a tab, what they do; made once.
const std::vector<std::string>& keyHelpLines();

// Sets the window's key, mouse and scroll callbacks, which act on `state` (the window's user
// pointer from now on).
void installInput(GLFWwindow* window, ViewerState* state);
