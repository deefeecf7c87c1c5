#include "world_position.h"

std::vector<float> worldPositions(const float* cameraRelative, size_t pixels, const glm::dvec3& eye) {
  std::vector<float> world(cameraRelative, cameraRelative + pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    float* p = &world[i * 4];
    if (p[3] == 0.0f) continue;  // the background: no position
    for (int c = 0; c < 3; ++c) p[c] = float(double(p[c]) + eye[c]);
  }
  return world;
}
