// Test scenes: fields of small spheres of the course's materials on the checker floor, as
// bench/sphere_field.py makes them.
#pragma once

#include "parser.h"
#include "scene.h"
#include "support/files.h"

#include <cmath>
#include <random>
#include <string>

// A field of `n` small spheres of the course's materials on the checker floor, as
// bench/sphere_field.py makes them, seen from `eye`.
inline Scene field(int n, const std::string& eye, const std::string& lookat = "(0, -1.5, -6)") {
  std::mt19937 rng{uint32_t(n)};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const char* materials[] = {"anImage", "aChecker", "aSolidChecker", "aNoise", "aMarble", "aWood", "aTurbulence",
                             "aDturbulence"};
  const double side = 2.0 * std::sqrt(double(n));
  std::string text = "#include \"texture_include.cfg\"\n"
                     "camera { eye = " + eye + "; lookat = " + lookat + "; up = (0, 1, 0); fov = 35; }\n"
                     "light { position = (-6, 10, 6); color = (1, 1, 1); }\n"
                     "plane { normal = (0, 1, 0); distance = -2; tex_scale = 5; aChecker; }\n";
  for (int i = 0; i < n; ++i) {
    const double r = 0.1 + 0.2 * unit(rng);
    const double x = (unit(rng) - 0.5) * side, z = -unit(rng) * side;
    text += "sphere { center = (" + std::to_string(x) + ", " + std::to_string(-2.0 + r) + ", " + std::to_string(z) +
            "); radius = " + std::to_string(r) + "; " + materials[i % 8] + "; }\n";
  }
  return parseSceneText(text, kSourceDir + "/scenes/sphere-field-test.cfg");
}

// A field with four lights (the course's; one low among the spheres; one above the field's
// middle; one behind the camera near the floor) and a wall behind it and one beside it.
inline Scene litField(int n, const std::string& eye) {
  Scene scene = field(n, eye);
  const double side = 2.0 * std::sqrt(double(n));
  auto light = [&](glm::dvec3 p) {
    Light l;
    l.position = p;
    l.color = glm::vec3(0.3f);
    scene.lights.push_back(l);
  };
  light({1.0, -1.6, -0.4 * side});
  light({0.0, 3.0, -0.5 * side});
  light({2.0, -1.0, 8.0});
  auto wall = [&](glm::dvec3 normal, double distance) {
    Plane p = scene.planes[0];
    p.normal = normal;
    p.distance = distance;
    scene.planes.push_back(p);
  };
  wall({0.0, 0.0, 1.0}, -side - 1.0);
  wall({1.0, 0.0, 0.0}, -0.5 * side - 1.0);
  return scene;
}
