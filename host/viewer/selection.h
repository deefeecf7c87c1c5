// What the viewer's keys act on: the object under the cursor (Tab), and the materials that
// 1-8 and M put on it, or on every sphere when nothing is selected. No Vulkan.
#pragma once

#include "reference.h"
#include "scene.h"
#include "scene_images.h"

#include <string>

struct Selection {
  int kind = 0;    // HIT_NONE (nothing selected), HIT_PLANE or HIT_SPHERE (common.h)
  int index = -1;  // into Scene::planes or Scene::spheres
};

// What the primary ray through the point (x, y) of a width x height view hits (pixels from the
// top-left corner; the cursor's position), with its texture coordinates; kind 0: nothing.
ReferenceHit hitAt(const Scene& scene, int width, int height, double x, double y);

// The object under (x, y), or nothing.
Selection objectAt(const Scene& scene, int width, int height, double x, double y);

// "sphere 2 (file:line)": the object as its scene file places it, counted from 1.
std::string selectionName(const Scene& scene, const Selection& selection);

// The material of the selected object, or of the first sphere when nothing is (-1: default).
int selectedMaterial(const Scene& scene, const Selection& selection);

// Puts material `index` on the selected object, or on every sphere when nothing is selected.
void applyMaterial(Scene& scene, const Selection& selection, int index);

// M: the material after `current` in the order the scene's own materials (those not named in
// `course`), then the course's it defines, wrapping; -1 when the scene defines none.
int nextMaterial(const Scene& scene, int current, const char* const* course, size_t courseCount);

// What the magnifier reports for the point under the cursor: the object, its (u, v), and the
// texel of an image (of `images`, by path) or the solid coordinate of a solid kind.
std::string pointReadout(const Scene& scene, const ReferenceHit& hit, const std::vector<SceneImage>& images);
