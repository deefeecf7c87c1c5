#include "standard_output.h"

#include "error.h"

#include <cerrno>
#include <cstring>
#include <string>

void finishStdout(FILE* out) {
  errno = 0;
  bool failed = fflush(out) != 0;
  int err = errno;
  failed = failed || ferror(out);
  if (!failed) return;
  if (err) throw IoError(std::string("cannot write to standard output: ") + strerror(err));
  throw IoError("cannot write to standard output");  // an earlier flush failed; its errno is gone
}
