// What the benchmarks share: their arguments and medians (machines are noisy).
#pragma once

#include "median.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

struct BenchArgs {
  std::string scene;
  uint32_t width = 1920, height = 1080;
  int runs = 5;
};

// SCENE [WIDTH HEIGHT RUNS]; false (usage printed) when SCENE is missing or a number is bad.
inline bool parseBenchArgs(int argc, char** argv, BenchArgs* args) {
  if (argc >= 2) args->scene = argv[1];
  if (argc > 3) {
    args->width = uint32_t(atoi(argv[2]));
    args->height = uint32_t(atoi(argv[3]));
  }
  if (argc > 4) args->runs = atoi(argv[4]);
  if (argc < 2 || args->width == 0 || args->height == 0 || args->runs < 1) {
    fprintf(stderr, "usage: %s SCENE [WIDTH HEIGHT RUNS]\n", argv[0]);
    return false;
  }
  return true;
}
