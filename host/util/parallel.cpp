#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

void forEachRowInParallel(int height, int threads, const std::function<void(int)>& rowFn) {
  std::atomic<int> nextRow{0};
  std::exception_ptr error;  // the first; a throw left in a thread would end the process
  std::mutex errorMutex;
  auto work = [&] {
    for (int y = nextRow++; y < height; y = nextRow++) {
      try {
        rowFn(y);
      } catch (...) {
        std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
        nextRow = height;  // no more rows
      }
    }
  };
  const int count = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int i = 1; i < count && i < height; ++i) {
    try {
      pool.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads: those started, and this one, do all the rows
    }
  }
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}
