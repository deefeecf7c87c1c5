#include "exit_status.h"

#include <cerrno>
#include <cstring>
#include <new>

std::string exceptionText(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  return e.what();
}

int runGuarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const std::exception& e) {
    fprintf(stderr, "raytex: %s\n", exceptionText(e).c_str());
  } catch (...) {
    fprintf(stderr, "raytex: unexpected internal error\n");
  }
  return 1;
}

int checkedExit(int rc, FILE* out) {
  errno = 0;
  bool failed = fflush(out) != 0;
  int err = errno;
  failed = failed || ferror(out);
  if (!failed) return rc;
  if (err)
    fprintf(stderr, "raytex: cannot write to standard output: %s\n", strerror(err));
  else  // an earlier flush failed; its errno is gone
    fprintf(stderr, "raytex: cannot write to standard output\n");
  return rc == 0 ? 1 : rc;
}
