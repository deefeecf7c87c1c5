#include "support/course_scene.h"
#include "support/files.h"

#include "parser.h"

#include <stdexcept>

const std::string& courseScenePath() {
  static const std::string path = kSourceDir + "/scenes/textures.cfg";
  return path;
}

int materialIndex(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return int(i);
  return -2;
}

Scene courseScene(const std::string& sphereMaterial, const std::string& planeMaterial) {
  Scene scene = parseSceneFile(courseScenePath());
  if (scene.spheres.size() != 1 || scene.planes.size() != 1)
    throw std::invalid_argument(courseScenePath() + ": not one sphere and one plane");
  auto index = [&](const std::string& name) {
    int i = materialIndex(scene, name);
    if (i < 0) throw std::invalid_argument("no material '" + name + "' in " + courseScenePath());
    return i;
  };
  scene.spheres[0].material = index(sphereMaterial);
  scene.planes[0].material = index(planeMaterial);
  return scene;
}
