// Standard output's last check: everything printed was written. No Vulkan.
#pragma once

#include <cstdio>

// Flushes `out` (stdout in main). Throws IoError "cannot write to standard output: ..." if any
// write to it failed.
void finishStdout(FILE* out);
