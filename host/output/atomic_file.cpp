#include "atomic_file.h"

#include "output_plan.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

[[noreturn]] void fail(const std::string& path, int err) {
  throw IoError("cannot write '" + path + "': " + strerror(err));
}

// The temporary files the signal handler removes: fixed buffers, as a handler may not allocate.
// One slot per output open at once (an image and its pass files).
constexpr int kMaxTemps = 16;
char gTempPaths[kMaxTemps][PATH_MAX];
volatile sig_atomic_t gTempRegistered[kMaxTemps] = {};

extern "C" void removeTempsAndReraise(int sig) {
  for (int i = 0; i < kMaxTemps; ++i)
    if (gTempRegistered[i]) unlink(gTempPaths[i]);
  raise(sig);  // SA_RESETHAND restored the default action: the exit status is the signal's
}

// Every signal whose default action ends the process, SIGKILL and SIGSTOP aside (they cannot be
// caught) and SIGXFSZ aside (ignored, below).
constexpr int kCleanupSignals[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT, SIGALRM,   SIGUSR1, SIGUSR2,
                                   SIGPIPE, SIGXCPU, SIGVTALRM, SIGPROF, SIGPOLL, SIGSYS,  SIGTRAP,
                                   SIGABRT, SIGBUS,  SIGFPE,  SIGILL,  SIGSEGV};
constexpr int kCleanupCount = int(sizeof kCleanupSignals / sizeof kCleanupSignals[0]);

// While any output is open: every signal that would end the process removes the registered
// temporary files first (a signal the process ignores, as `nohup` ignores SIGHUP, stays
// ignored), and SIGXFSZ is ignored so that a file size limit is a write error. The first output
// open installs these actions; when the last one closes, the previous actions come back.
struct SignalState {
  int holders = 0;
  struct sigaction previous[kCleanupCount] = {}, previousXfsz = {};
};
SignalState gSignals;

void holdSignals() {
  if (gSignals.holders++ > 0) return;
  struct sigaction cleanup = {};
  cleanup.sa_handler = removeTempsAndReraise;
  cleanup.sa_flags = SA_RESETHAND;
  sigemptyset(&cleanup.sa_mask);
  for (int i = 0; i < kCleanupCount; ++i) {
    sigaction(kCleanupSignals[i], nullptr, &gSignals.previous[i]);
    if (gSignals.previous[i].sa_handler != SIG_IGN) sigaction(kCleanupSignals[i], &cleanup, nullptr);
  }
  struct sigaction ignore = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGXFSZ, &ignore, &gSignals.previousXfsz);
}

void releaseSignals() {
  if (--gSignals.holders > 0) return;
  for (int i = 0; i < kCleanupCount; ++i) sigaction(kCleanupSignals[i], &gSignals.previous[i], nullptr);
  sigaction(SIGXFSZ, &gSignals.previousXfsz, nullptr);
}

// Runs `step` with every signal that can be held back held back, so that a handler never sees a
// half-done registration and no signal ends the process between naming a file and renaming it.
template <typename F>
void withSignalsBlocked(F step) {
  sigset_t all, old;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &old);
  step();
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

// Test hook: with the environment variable RAYTEX_TEST_PAUSE_IN_WRITE set, the process stops
// itself (SIGSTOP) once, half-way through its first write, so that a test can signal it in the
// middle of a write.
bool gPausedInWrite = false;

// Writes all of `data` to `fd`, at `offset` when it is not negative (pwrite), else where the
// file offset is; false with errno set on failure.
bool writeAll(int fd, const uint8_t* data, size_t size, int64_t offset) {
  const size_t half = !gPausedInWrite && getenv("RAYTEX_TEST_PAUSE_IN_WRITE") ? size / 2 : 0;
  size_t written = 0;
  while (written < size) {
    size_t end = written < half ? half : size;
    ssize_t n = offset < 0 ? ::write(fd, data + written, end - written)
                           : pwrite(fd, data + written, end - written, off_t(offset + int64_t(written)));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    written += size_t(n);
    if (half > 0 && written == half) {
      gPausedInWrite = true;
      raise(SIGSTOP);
    }
  }
  return true;
}

// A device, FIFO or other non-regular file: written in place. A FIFO is opened without
// blocking, so that one with no reader is an error (ENXIO) rather than a wait.
int openThrough(const std::string& path, const std::string& target) {
  int fd = open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 && errno == ENXIO)
    throw IoError("cannot write '" + path + "': no process is reading it");
  if (fd < 0) fail(path, errno);
  int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

// The directory a regular output's file is made in: the target's.
std::string directoryOf(const std::string& target) {
  size_t slash = target.rfind('/');
  return slash == std::string::npos ? "." : target.substr(0, slash + 1);
}

// An existing file's mode is kept; a new one gets the usual 0666 & ~umask.
void setMode(int fd, const struct stat* existing) {
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, existing ? existing->st_mode & 07777 : 0666 & ~mask);
}

// A file with no name in the target's directory (O_TMPFILE), named only at commit: no signal,
// not even SIGKILL, can leave it behind. -1 where the file system refuses O_TMPFILE or
// /proc/self/fd, which commit links it through, is missing; then the named temporary serves.
// RAYTEX_TEST_NAMED_TEMP=1 makes every output take the named temporary (for its tests).
int openUnnamed(const std::string& target) {
  if (getenv("RAYTEX_TEST_NAMED_TEMP")) return -1;
  int fd = open(directoryOf(target).c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) return -1;
  char link[64];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  if (access(link, F_OK) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

// The named temporary file beside the target, registered for the signal handler in `*slot`.
int openNamedTemp(const std::string& path, const std::string& target, std::string* tmp, int* slot) {
  long nameMax = pathconf(directoryOf(target).c_str(), _PC_NAME_MAX);
  *tmp = tempTemplate(target, nameMax > 0 ? size_t(nameMax) : 255);
  if (tmp->size() >= PATH_MAX) fail(path, ENAMETOOLONG);
  int fd = -1, err = 0;
  withSignalsBlocked([&] {
    int i = 0;
    while (i < kMaxTemps && gTempRegistered[i]) ++i;
    fd = i < kMaxTemps ? mkstemp(tmp->data()) : -1;
    err = i < kMaxTemps ? errno : EMFILE;
    if (fd < 0) return;
    memcpy(gTempPaths[i], tmp->c_str(), tmp->size() + 1);
    gTempRegistered[i] = 1;
    *slot = i;
  });
  if (fd < 0) fail(path, err);
  return fd;
}

// Gives the unnamed file `fd` the target's name: linked under a fresh temporary name beside
// it, then renamed over the target, with every signal held back in between. 0, or the errno.
int publishUnnamed(int fd, const std::string& target) {
  char from[64];
  snprintf(from, sizeof from, "/proc/self/fd/%d", fd);
  long nameMax = pathconf(directoryOf(target).c_str(), _PC_NAME_MAX);
  std::string name = tempTemplate(target, nameMax > 0 ? size_t(nameMax) : 255);
  int err = EEXIST;
  withSignalsBlocked([&] {
    for (int attempt = 0; attempt < 100 && err == EEXIST; ++attempt) {
      uint8_t random[6] = {};
      if (getrandom(random, sizeof random, 0) != sizeof random) random[0] = uint8_t(attempt);
      static const char digits[] = "abcdefghijklmnopqrstuvwxyz0123456789";
      for (size_t i = 0; i < 6; ++i) name[name.size() - 6 + i] = digits[random[i] % 36];
      err = linkat(AT_FDCWD, from, AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0 ? 0 : errno;
    }
    if (err != 0) return;
    if (rename(name.c_str(), target.c_str()) != 0) {
      err = errno;
      unlink(name.c_str());
    }
  });
  return err;
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  if (path == "-") {
    kind_ = Kind::Stdout;
    return;
  }
  target_ = writeTarget(path);
  struct stat st;
  const bool exists = stat(target_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) fail(path, EISDIR);
  kind_ = exists && !S_ISREG(st.st_mode) ? Kind::Through : Kind::Unnamed;
  holdSignals();
  signalsHeld_ = true;
  try {
    if (kind_ == Kind::Through) {
      fd_ = openThrough(path, target_);
      return;
    }
    fd_ = openUnnamed(target_);
    if (fd_ < 0) {
      kind_ = Kind::Replace;
      fd_ = openNamedTemp(path, target_, &temp_, &slot_);
    }
    setMode(fd_, exists ? &st : nullptr);
  } catch (...) {
    releaseSignals();
    throw;
  }
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) close(fd_);
  if (slot_ >= 0) {
    withSignalsBlocked([&] {
      unlink(temp_.c_str());
      gTempRegistered[slot_] = 0;
    });
  }
  if (signalsHeld_) releaseSignals();
}

void AtomicFile::write(const uint8_t* data, size_t size) {
  if (kind_ == Kind::Stdout) {
    // Errors show at the final flush (main.cpp), with their errno.
    if (fwrite(data, 1, size, stdout) != size)
      throw IoError(std::string("cannot write to standard output: ") + strerror(errno));
    return;
  }
  if (!writeAll(fd_, data, size, -1)) fail(path_, errno);
}

void AtomicFile::writeAt(uint64_t offset, const uint8_t* data, size_t size) {
  if (!seekable()) throw Error(ErrorKind::Internal, "'" + path_ + "' cannot be written out of order");
  if (!writeAll(fd_, data, size, int64_t(offset))) fail(path_, errno);
}

void AtomicFile::commit() {
  if (committed_ || kind_ == Kind::Stdout) {
    committed_ = true;
    return;
  }
  if (kind_ == Kind::Unnamed) {
    if (int err = publishUnnamed(fd_, target_)) fail(path_, err);  // the destructor closes the file
    published_ = true;
  }
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) fail(path_, errno);  // the destructor removes the temporary
  if (kind_ == Kind::Replace) {
    if (rename(temp_.c_str(), target_.c_str()) != 0) fail(path_, errno);
    withSignalsBlocked([&] { gTempRegistered[slot_] = 0; });
    slot_ = -1;
    published_ = true;
  }
  releaseSignals();
  signalsHeld_ = false;
  committed_ = true;
}

void AtomicFile::withdraw() {
  if (published_) unlink(target_.c_str());
  published_ = false;
}

std::string tempTemplate(const std::string& path, size_t nameMax) {
  static const std::string suffix = ".tmp-XXXXXX";
  size_t slash = path.rfind('/');
  size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
  std::string name = path.substr(nameStart);
  if (nameMax > suffix.size() && name.size() + suffix.size() > nameMax) {
    size_t keep = nameMax - suffix.size();
    while (keep > 0 && (uint8_t(name[keep]) & 0xC0) == 0x80) --keep;  // not inside a character
    name.resize(keep);
  }
  return path.substr(0, nameStart) + name + suffix;
}

void writeFileAtomic(const std::string& path, const std::vector<uint8_t>& bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

void writePngAtomic(const std::string& path, const ImageRGBA8& image) {
  std::vector<uint8_t> png = encodePng(image);
  if (png.empty()) throw Error(ErrorKind::Internal, "cannot encode PNG for '" + path + "'");
  writeOutput(path, png);
}

void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes) { writeFileAtomic(path, bytes); }

void finishStdout(FILE* out) {
  errno = 0;
  bool failed = fflush(out) != 0;
  int err = errno;
  failed = failed || ferror(out);
  if (!failed) return;
  if (err) throw IoError(std::string("cannot write to standard output: ") + strerror(err));
  throw IoError("cannot write to standard output");  // an earlier flush failed; its errno is gone
}
