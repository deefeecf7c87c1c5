#include "scene.h"

std::string formatLoc(const FileLoc& loc, const std::string& message) {
  if (loc.line <= 0) return loc.file + ": " + message;  // about the whole file (cannot open it)
  return loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column) + ": " + message;
}

Material defaultMaterial() {
  Material m;
  m.name = "default";
  m.ambient = glm::vec3(0.1f);
  m.diffuse = glm::vec3(0.7f);
  m.specular = glm::vec3(0.3f);
  m.shininess = 32.0f;
  return m;
}
