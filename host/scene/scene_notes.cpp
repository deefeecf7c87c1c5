#include "scene_notes.h"

namespace {

// The names of the scene's textured materials, the first four and "..." after them.
std::string texturedMaterialNames(const Scene& scene, std::string* first) {
  std::string names;
  int listed = 0;
  for (const Material& m : scene.materials) {
    if (m.texture.kind == TextureKind::None) continue;
    if (listed == 0) *first = m.name;
    if (listed == 4) return names + ", ...";
    names += (listed++ > 0 ? ", " : "") + m.name;
  }
  return names;
}

// The first object in the default material ("sphere" or "plane" and its location) and how
// many others are.
int objectsInDefaultMaterial(const Scene& scene, const char** kind, FileLoc* loc) {
  int count = 0;
  auto look = [&](int material, const char* what, const FileLoc& where) {
    if (material >= 0) return;
    if (count++ == 0) *kind = what, *loc = where;
  };
  for (const Sphere& s : scene.spheres) look(s.material, "sphere", s.loc);
  for (const Plane& p : scene.planes) look(p.material, "plane", p.loc);
  return count;
}

}  // namespace

std::vector<std::string> sceneNotes(const Scene& scene) {
  std::vector<std::string> notes;
  std::string example;
  const std::string textured = texturedMaterialNames(scene, &example);
  const char* kind = "";
  FileLoc loc;
  const int plain = objectsInDefaultMaterial(scene, &kind, &loc);
  if (plain == 0 || textured.empty()) return notes;
  std::string others = plain == 1 ? "" : " (and " + std::to_string(plain - 1) + " more object" +
                                              (plain == 2 ? "" : "s") + ")";
  notes.push_back(formatLoc(loc, "note: this " + std::string(kind) + others +
                                     " names no material, so it is plain grey (the default material); the "
                                     "scene defines textured materials (" + textured +
                                     "): to use one, name it inside the object's block, e.g. '" + example + ";'"));
  return notes;
}

void printSceneNotes(const Scene& scene, FILE* out) {
  for (const std::string& note : sceneNotes(scene)) fprintf(out, "%s\n", note.c_str());
}
