// What the viewer's keys, mouse and frame loop share: the scene on screen and its camera's
// orbit, the selection, the overlays and methods that are on, and the course's materials that
// the keys put on objects. No Vulkan, no window.
#pragma once

#include "gpu_scene.h"
#include "scene.h"
#include "selection.h"

#include <glm/vec3.hpp>

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

using Clock = std::chrono::steady_clock;

// The course's materials, in the order of the notes; keys 1-8 put them on the selection.
constexpr size_t kCourseMaterialCount = 8;
extern const char* const kCourseMaterials[kCourseMaterialCount];

// How long a message stays in the title.
constexpr std::chrono::seconds kMessageTime{3};

// The camera orbits its lookat point about the scene's up axis: eye = lookat + radius *
// (cos(elevation) (cos(azimuth) e1 + sin(azimuth) e2) + sin(elevation) up).
struct Orbit {
  Camera home;               // the scene file's camera (R returns to it)
  glm::dvec3 up{0, 1, 0}, e1{1, 0, 0}, e2{0, 0, 1};
  double radius = 1.0, azimuth = 0.0, elevation = 0.0;
};

Orbit orbitOf(const Camera& camera);

// The scene on screen before a reload, kept until the reloaded scene has rendered a sample:
// a reloaded scene the kernel fails (LoopBudgetError: a sphere tree's walks, known only as they
// run) gives way to it. `packed`: its GPU data, set once the reloaded scene replaces it on the
// device, packed with mip chains or not.
struct LastGoodScene {
  Scene scene;
  Orbit orbit;
  Selection selection;
  std::optional<GpuScene> packed;
  bool mipmaps = false;
};

struct ViewerState {
  Scene scene;
  Orbit orbit;
  bool dirty = true;         // the GPU scene must be rebuilt (size or scene file changed)
  bool cameraMoved = false;  // the camera or an object's material changed: re-pack the objects
  bool dragging = false;
  double lastX = 0.0, lastY = 0.0;
  double cursorX = 0.0, cursorY = 0.0;  // in the image's pixels
  bool screenshot = false;   // write the image to the output PNG once it has every sample
  bool refresh = false;      // the window needs the image again (exposed, an overlay changed)
  int planeMaterial = -1;    // index into kCourseMaterials for P cycling
  Selection selection;       // Tab: what 1-8 and M change (nothing: every sphere)
  bool help = false;         // H: the keys over the image
  bool magnifier = false;    // Z held: the pixels around the cursor enlarged
  bool uvPass = false;       // U: the uv pass instead of the image
  TextureFilter filter = TextureFilter::Point;       // the render's method (the job's), left of the split
  bool split = false;                                // V: another method right of the split
  TextureFilter splitFilter = TextureFilter::Box;    // B: that method
  double splitAt = 0.5;                              // the split's column, a fraction of the width
  bool splitDragging = false;                        // the right mouse button moves the split
  bool sceneError = false;   // the scene's files on disk do not load; the last good scene shows
  bool specialisedPending = false;  // the all-kinds kernel renders until the specialised ones are compiled
  std::string message;       // shown in the title for kMessageTime (e.g. "wrote shot.png")
  Clock::time_point messageAt;
  std::optional<Clock::time_point> switchedAt;  // a material key, until its frame is shown
  std::optional<GpuScene> reloaded;  // a reloaded scene's GPU data, its images checked and decoded
  std::optional<LastGoodScene> lastGood;  // until a reloaded scene has rendered a sample
};

// The index of the scene's material `name`, or -1.
int materialIndex(const Scene& scene, const char* name);
// A material's name; "default" for -1.
std::string materialName(const Scene& scene, int index);

// Moves the camera by angles (radians) and a zoom factor, elevation kept off the poles.
void moveCamera(ViewerState& state, double dAzimuth, double dElevation, double zoom);

// A message in the title for kMessageTime.
void say(ViewerState& state, std::string message);

// The method after `filter` that is not `except`: point, box, coverage, cycling.
TextureFilter nextFilter(TextureFilter filter, TextureFilter except);
