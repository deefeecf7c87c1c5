#include "camera_block.h"

#include <cstdio>
#include <cstdlib>

namespace {

std::string number(double v) {
  char text[32];
  snprintf(text, sizeof(text), "%.9g", v);
  return text;
}

std::string tuple(const glm::dvec3& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

double printed(double v) { return std::strtod(number(v).c_str(), nullptr); }

glm::dvec3 printed(const glm::dvec3& v) { return {printed(v.x), printed(v.y), printed(v.z)}; }

}  // namespace

std::string cameraBlock(const Camera& camera) {
  return "camera {\n"
         "    eye = " + tuple(camera.eye) + ";\n"
         "    lookat = " + tuple(camera.lookat) + ";\n"
         "    up = " + tuple(camera.up) + ";\n"
         "    fov = " + number(camera.fovY) + ";\n"
         "}\n";
}

Camera printedCamera(const Camera& camera) {
  Camera c;
  c.eye = printed(camera.eye);
  c.lookat = printed(camera.lookat);
  c.up = printed(camera.up);
  c.fovY = printed(camera.fovY);
  return c;
}
