// How the process ends: one top-level handler for exceptions nothing else caught, and a check
// that everything printed to stdout was written. No Vulkan.
#pragma once

#include <cstdio>
#include <exception>
#include <functional>
#include <string>

// A caught exception as one line of text: "out of memory" for std::bad_alloc, else what().
std::string exceptionText(const std::exception& e);

// Runs `command` and returns its exit code; an exception that escapes it becomes one line
// "raytex: ..." on stderr and exit code 1.
int runGuarded(const std::function<int()>& command);

// Flushes `out` (stdout in main); if any write to it failed, prints "raytex: cannot write to
// standard output: ..." on stderr and returns 1 where `rc` was 0. Otherwise returns `rc`.
int checkedExit(int rc, FILE* out);
