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

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

// While any output is open: SIGINT, SIGTERM and SIGHUP remove the registered temporary files
// (unless the process ignores them, as `nohup` and background jobs do), and SIGXFSZ is ignored
// so that a file size limit is a write error. The first output open installs these actions;
// when the last one closes, the previous actions come back.
struct SignalState {
  int holders = 0;
  struct sigaction previous[3] = {}, previousXfsz = {};
};
SignalState gSignals;

void holdSignals() {
  if (gSignals.holders++ > 0) return;
  struct sigaction cleanup = {};
  cleanup.sa_handler = removeTempsAndReraise;
  cleanup.sa_flags = SA_RESETHAND;
  sigemptyset(&cleanup.sa_mask);
  for (int i = 0; i < 3; ++i) {
    sigaction(kCleanupSignals[i], nullptr, &gSignals.previous[i]);
    if (gSignals.previous[i].sa_handler != SIG_IGN) sigaction(kCleanupSignals[i], &cleanup, nullptr);
  }
  struct sigaction ignore = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGXFSZ, &ignore, &gSignals.previousXfsz);
}

void releaseSignals() {
  if (--gSignals.holders > 0) return;
  for (int i = 0; i < 3; ++i) sigaction(kCleanupSignals[i], &gSignals.previous[i], nullptr);
  sigaction(SIGXFSZ, &gSignals.previousXfsz, nullptr);
}

// Runs `step` with the cleanup signals held back, so that the handler never sees a half-done
// registration.
template <typename F>
void withSignalsBlocked(F step) {
  sigset_t cleanupSet, old;
  sigemptyset(&cleanupSet);
  for (int sig : kCleanupSignals) sigaddset(&cleanupSet, sig);
  pthread_sigmask(SIG_BLOCK, &cleanupSet, &old);
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
int openThrough(const std::string& path, const std::string& target) {
  int fd = open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 && errno == ENXIO)
    throw IoError("cannot write '" + path + "': no process is reading it");
  if (fd < 0) fail(path, errno);
  int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

// A regular file, new or existing: the temporary file beside it, registered for the signal
// handler in `*slot`. An existing file's mode is the temporary's (mkstemp creates 0600); a new
// one gets the usual 0666 & ~umask.
int openTemp(const std::string& path, const std::string& target, const struct stat* existing, std::string* tmp,
             int* slot) {
  size_t slash = target.rfind('/');
  std::string dir = slash == std::string::npos ? "." : target.substr(0, slash + 1);
  long nameMax = pathconf(dir.c_str(), _PC_NAME_MAX);
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
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, existing ? existing->st_mode & 07777 : 0666 & ~mask);
  return fd;
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(path) {
  if (path == "-") {
    kind_ = Kind::Stdout;
    return;
  }
  target_ = followLinks(path);
  struct stat st;
  const bool exists = stat(target_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) fail(path, EISDIR);
  kind_ = exists && !S_ISREG(st.st_mode) ? Kind::Through : Kind::Replace;
  holdSignals();
  signalsHeld_ = true;
  try {
    fd_ = kind_ == Kind::Through ? openThrough(path, target_)
                                 : openTemp(path, target_, exists ? &st : nullptr, &temp_, &slot_);
  } catch (...) {
    releaseSignals();
    throw;
  }
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) close(fd_);
  if (slot_ >= 0) {
    withSignalsBlocked([&] {
      unlink(temp_.c_str());
      gTempRegistered[slot_] = 0;
    });
  }
  if (signalsHeld_) releaseSignals();
}

void OutputFile::write(const uint8_t* data, size_t size) {
  if (kind_ == Kind::Stdout) {
    // Errors show at the final flush (main.cpp), with their errno.
    if (fwrite(data, 1, size, stdout) != size)
      throw IoError(std::string("cannot write to standard output: ") + strerror(errno));
    return;
  }
  if (!writeAll(fd_, data, size, -1)) fail(path_, errno);
}

void OutputFile::writeAt(uint64_t offset, const uint8_t* data, size_t size) {
  if (!seekable()) throw Error(ErrorKind::Internal, "'" + path_ + "' cannot be written out of order");
  if (!writeAll(fd_, data, size, int64_t(offset))) fail(path_, errno);
}

void OutputFile::commit() {
  if (committed_ || kind_ == Kind::Stdout) {
    committed_ = true;
    return;
  }
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) fail(path_, errno);  // the destructor removes the temporary
  if (kind_ == Kind::Replace) {
    if (rename(temp_.c_str(), target_.c_str()) != 0) fail(path_, errno);
    withSignalsBlocked([&] { gTempRegistered[slot_] = 0; });
    slot_ = -1;
  }
  releaseSignals();
  signalsHeld_ = false;
  committed_ = true;
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
  OutputFile file(path);
  file.write(bytes);
  file.commit();
}

void writePngAtomic(const std::string& path, const ImageRGBA8& image) {
  std::vector<uint8_t> png = encodePng(image);
  if (png.empty()) throw Error(ErrorKind::Internal, "cannot encode PNG for '" + path + "'");
  writeOutput(path, png);
}

void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes) { writeFileAtomic(path, bytes); }

OutputFormat outputFormatFor(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".png") return OutputFormat::Png;
  if (ext == ".exr") return OutputFormat::Exr;
  if (ext == ".pfm") return OutputFormat::Pfm;
  struct stat st;
  if (path == "-" || (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)))
    return OutputFormat::Png;  // written through whatever its name
  throw UsageError("'" + path + "': unknown output format (supported: .png, .exr, .pfm)");
}

void checkOutput(const std::string& output, const Scene& scene) {
  if (output.empty() || output == "-") return;
  if (std::string clash = outputClash(output, scene); !clash.empty()) throw UsageError(clash);
  outputFormatFor(output);
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
