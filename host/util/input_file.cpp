#include "input_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

int openRegularFile(const std::string& path, std::string* why) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    *why = strerror(errno);
    return -1;
  }
  if (!S_ISREG(st.st_mode)) {
    *why = "not a regular file";
    return -1;
  }
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    *why = strerror(errno);
    return -1;
  }
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {  // replaced since the stat
    close(fd);
    *why = "not a regular file";
    return -1;
  }
  const int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

FILE* openRegularStream(const std::string& path, std::string* why) {
  const int fd = openRegularFile(path, why);
  if (fd < 0) return nullptr;
  FILE* file = fdopen(fd, "rb");
  if (!file) {
    *why = strerror(errno);
    close(fd);
  }
  return file;
}

namespace {

// Reads until the end of the file into `text` (holding `expected` bytes), but never more than
// maxBytes + 1 bytes in all; false with errno set when a read fails.
bool readToEnd(int fd, uint64_t expected, uint64_t maxBytes, std::string* text) {
  text->resize(size_t(expected));
  size_t used = 0;
  for (;;) {
    if (used == text->size()) {
      if (used > maxBytes) return true;  // grown past the limit: the caller refuses it
      text->resize(size_t(std::min<uint64_t>(maxBytes + 1, uint64_t(used) + 65536)));
    }
    const ssize_t n = read(fd, text->data() + used, text->size() - used);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) break;
    used += size_t(n);
  }
  text->resize(used);
  return true;
}

}  // namespace

ReadStatus readWholeFile(const std::string& path, uint64_t maxBytes, std::string* text, std::string* why,
                         uint64_t* size) {
  const int fd = openRegularFile(path, why);
  if (fd < 0) return ReadStatus::CannotOpen;
  struct stat st {};
  fstat(fd, &st);
  *size = uint64_t(st.st_size);
  if (*size > maxBytes) {
    close(fd);
    return ReadStatus::TooLarge;
  }
  bool ok = false;
  try {
    ok = readToEnd(fd, *size, maxBytes, text);
  } catch (...) {
    close(fd);
    throw;
  }
  const int err = errno;
  close(fd);
  if (!ok) {
    *why = strerror(err);
    return ReadStatus::ReadFailed;
  }
  if (text->size() > maxBytes) {
    *size = text->size();
    text->clear();
    return ReadStatus::TooLarge;
  }
  return ReadStatus::Read;
}
