// Rows of an image, or any run of indices, shared out between threads. No Vulkan.
#pragma once

#include <functional>

// rowFn(y) for every y in [0, height), rows handed out one at a time to `threads` threads
// (0: one per processor thread); this thread works too. An exception in a row is rethrown
// here once all threads are done.
void forEachRowInParallel(int height, int threads, const std::function<void(int)>& rowFn);
