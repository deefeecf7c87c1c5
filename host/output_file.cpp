#include "output_file.h"

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
#include <sys/stat.h>
#include <unistd.h>

namespace {

[[noreturn]] void fail(const std::string& path, int err) {
  throw IoError("cannot write '" + path + "': " + strerror(err));
}

// The temporary file the signal handler removes: a fixed buffer, as a handler may not allocate.
char gTempPath[PATH_MAX];
volatile sig_atomic_t gTempRegistered = 0;

extern "C" void removeTempAndReraise(int sig) {
  if (gTempRegistered) unlink(gTempPath);
  raise(sig);  // SA_RESETHAND restored the default action: the exit status is the signal's
}

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

// While alive: SIGINT, SIGTERM and SIGHUP remove the registered temporary file (unless the
// process ignores them, as `nohup` and background jobs do), and SIGXFSZ is ignored so that a
// file size limit is a write error. The previous actions come back on destruction.
struct SignalGuard {
  struct sigaction previous[3] = {}, previousXfsz = {};
  sigset_t cleanupSet;
  SignalGuard() {
    sigemptyset(&cleanupSet);
    for (int sig : kCleanupSignals) sigaddset(&cleanupSet, sig);
    struct sigaction cleanup = {};
    cleanup.sa_handler = removeTempAndReraise;
    cleanup.sa_flags = SA_RESETHAND;
    sigemptyset(&cleanup.sa_mask);
    for (int i = 0; i < 3; ++i) {
      sigaction(kCleanupSignals[i], nullptr, &previous[i]);
      if (previous[i].sa_handler != SIG_IGN) sigaction(kCleanupSignals[i], &cleanup, nullptr);
    }
    struct sigaction ignore = {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGXFSZ, &ignore, &previousXfsz);
  }
  ~SignalGuard() {
    for (int i = 0; i < 3; ++i) sigaction(kCleanupSignals[i], &previous[i], nullptr);
    sigaction(SIGXFSZ, &previousXfsz, nullptr);
  }
  // Runs `step` with the cleanup signals held back, so that the handler never sees a half-done
  // registration.
  template <typename F>
  void withSignalsBlocked(F step) {
    sigset_t old;
    pthread_sigmask(SIG_BLOCK, &cleanupSet, &old);
    step();
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
  }
};

// Writes all of `bytes` to `fd`; false with errno set on failure. Test hook: with the
// environment variable RAYTEX_TEST_PAUSE_IN_WRITE set, the process stops itself (SIGSTOP) after
// the first half, so that a test can signal it in the middle of a write.
bool writeAll(int fd, const std::vector<uint8_t>& bytes) {
  const size_t half = getenv("RAYTEX_TEST_PAUSE_IN_WRITE") ? bytes.size() / 2 : 0;
  size_t written = 0;
  while (written < bytes.size()) {
    size_t end = written < half ? half : bytes.size();
    ssize_t n = write(fd, bytes.data() + written, end - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    written += size_t(n);
    if (written == half) raise(SIGSTOP);
  }
  return true;
}

// `path` with its symbolic links followed to the file they name (which may not exist yet).
std::string followLinks(const std::string& path) {
  std::string p = path;
  for (int depth = 0; depth < 40; ++depth) {
    struct stat st;
    if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string target(size_t(st.st_size > 0 ? st.st_size : PATH_MAX), '\0');
    ssize_t n = readlink(p.c_str(), target.data(), target.size());
    if (n <= 0) return p;
    target.resize(size_t(n));
    size_t slash = p.rfind('/');
    std::string next = target[0] == '/' || slash == std::string::npos ? target : p.substr(0, slash + 1) + target;
    // A link only the kernel can follow (/proc/self/fd/1 -> "pipe:[N]", as /dev/stdout is): kept.
    if (lstat(next.c_str(), &st) != 0 && stat(p.c_str(), &st) == 0) return p;
    p = next;
  }
  return p;  // a loop: the open or rename reports ELOOP
}

// A device, FIFO or other non-regular file: written in place. A FIFO is opened without
// blocking, so that one with no reader is an error (ENXIO) rather than a wait.
void writeThrough(const std::string& path, const std::string& target, const std::vector<uint8_t>& bytes) {
  int fd = open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 && errno == ENXIO)
    throw IoError("cannot write '" + path + "': no process is reading it");
  if (fd < 0) fail(path, errno);
  int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  bool ok = writeAll(fd, bytes);
  int err = errno;
  if (close(fd) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (!ok) fail(path, err);
}

// A regular file, new or existing: a temporary file beside it, then a rename.
void writeReplacing(const std::string& path, const std::string& target, const struct stat* existing,
                    const std::vector<uint8_t>& bytes) {
  size_t slash = target.rfind('/');
  std::string dir = slash == std::string::npos ? "." : target.substr(0, slash + 1);
  long nameMax = pathconf(dir.c_str(), _PC_NAME_MAX);
  std::string tmp = tempTemplate(target, nameMax > 0 ? size_t(nameMax) : 255);
  if (tmp.size() >= sizeof(gTempPath)) fail(path, ENAMETOOLONG);
  SignalGuard guard;
  int fd = -1;
  guard.withSignalsBlocked([&] {
    fd = mkstemp(tmp.data());
    if (fd < 0) return;
    memcpy(gTempPath, tmp.c_str(), tmp.size() + 1);
    gTempRegistered = 1;
  });
  if (fd < 0) fail(path, errno);
  // mkstemp creates 0600: an existing file keeps its mode, a new one gets the usual one.
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, existing ? existing->st_mode & 07777 : 0666 & ~mask);
  bool ok = writeAll(fd, bytes);
  int err = errno;
  if (close(fd) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (ok && rename(tmp.c_str(), target.c_str()) != 0) {
    ok = false;
    err = errno;
  }
  guard.withSignalsBlocked([&] {
    if (!ok) unlink(tmp.c_str());
    gTempRegistered = 0;
  });
  if (!ok) fail(path, err);
}

}  // namespace

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
  std::string target = followLinks(path);
  struct stat st;
  bool exists = stat(target.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) fail(path, EISDIR);
  if (exists && !S_ISREG(st.st_mode)) {
    SignalGuard guard;  // SIGXFSZ ignored; there is no temporary file to remove
    writeThrough(path, target, bytes);
    return;
  }
  writeReplacing(path, target, exists ? &st : nullptr, bytes);
}

void writePngAtomic(const std::string& path, const ImageRGBA8& image) {
  std::vector<uint8_t> png = encodePng(image);
  if (png.empty()) throw Error(ErrorKind::Internal, "cannot encode PNG for '" + path + "'");
  writeOutput(path, png);
}

void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes) {
  if (path != "-") {
    writeFileAtomic(path, bytes);
    return;
  }
  // Errors show at the final flush (main.cpp), with their errno.
  if (fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size())
    throw IoError(std::string("cannot write to standard output: ") + strerror(errno));
}

void checkOutput(const std::string& output, const Scene& scene) {
  if (output.empty() || output == "-") return;
  if (std::string clash = outputClash(output, scene); !clash.empty()) throw UsageError(clash);
  struct stat st;
  if (stat(output.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) return;  // written through
  std::string ext = std::filesystem::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".png")
    throw UsageError("cannot write '" + output + "': raytex writes PNG files (.png), or - for standard output");
}

std::string outputClash(const std::string& output, const Scene& scene) {
  struct stat out;
  if (output.empty() || stat(output.c_str(), &out) != 0) return "";  // a new file clashes with nothing
  auto same = [&](const std::string& input) {
    struct stat in;
    return stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino;
  };
  std::string what;
  if (same(scene.path)) what = "the scene file";
  for (size_t i = 0; what.empty() && i < scene.files.size(); ++i)
    if (same(scene.files[i])) what = i == 0 ? "the scene file" : "a file the scene includes";
  for (const Material& m : scene.materials)
    if (what.empty() && m.texture.kind == TextureKind::Image && same(m.texture.imagePath))
      what = "an image the scene uses";
  return what.empty() ? "" : "refusing to write '" + output + "': it is " + what;
}
