#include "output_plan.h"

#include "error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// What makes two paths one file: device and inode where the file exists (after every link),
// else the absolute path with links resolved as far as it exists.
struct FileIdentity {
  bool exists = false;
  struct stat st {};
  std::string canonical;
};

FileIdentity identify(const std::string& path) {
  FileIdentity id;
  const std::string target = writeTarget(path);
  id.exists = stat(target.c_str(), &id.st) == 0;
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(target, ec), ec);
  id.canonical = ec ? target : p.string();
  return id;
}

bool sameFile(const FileIdentity& a, const FileIdentity& b) {
  if (a.exists && b.exists) return a.st.st_dev == b.st.st_dev && a.st.st_ino == b.st.st_ino;
  return !a.exists && !b.exists && a.canonical == b.canonical;
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// A file raytex may create or replace at `write.path`, judged before anything is written.
void checkWritable(const PlannedWrite& write, const FileIdentity& id) {
  const std::string& path = write.path;
  if (id.exists && S_ISDIR(id.st.st_mode)) throw IoError("cannot write " + quoted(path) + ": " + strerror(EISDIR));
  if (id.exists && !S_ISREG(id.st.st_mode)) {
    if (write.named) return;  // a device or FIFO the user named: written through
    throw UsageError("refusing to write " + quoted(path) + " (" + write.what +
                     "): it exists and is not a regular file (only an output named on the command line is "
                     "written through)");
  }
  const std::string target = writeTarget(path);
  if (target.size() >= PATH_MAX)
    throw UsageError("cannot write " + quoted(path) + ": the path is " + std::to_string(target.size()) +
                     " bytes, more than the " + std::to_string(PATH_MAX - 1) + " a path may have");
  const size_t slash = target.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : target.substr(0, slash);
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  struct stat dirSt;
  if (stat(dir.c_str(), &dirSt) != 0) throw IoError("cannot write " + quoted(path) + ": " + strerror(errno));
  if (!S_ISDIR(dirSt.st_mode)) throw IoError("cannot write " + quoted(path) + ": " + strerror(ENOTDIR));
  const long nameMax = pathconf(dir.c_str(), _PC_NAME_MAX);
  if (nameMax > 0 && name.size() > size_t(nameMax))
    throw UsageError("cannot write " + quoted(path) + ": its name is " + std::to_string(name.size()) +
                     " bytes, more than the " + std::to_string(nameMax) + " its directory allows");
}

// A pass file goes beside a regular file (or a new one): never into /dev beside a device.
void checkBeside(const PlannedWrite& write) {
  struct stat st;
  if (write.beside.empty() || stat(write.beside.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return;
  throw UsageError("refusing to write " + quoted(write.path) + " (" + write.what + ") beside " +
                   quoted(write.beside) + ", which is not a regular file: write the passes into an EXR, or "
                   "beside a file");
}

void checkRead(const PlannedRead& read, const FileIdentity& id) {
  if (!read.requireRegular) return;
  if (!id.exists) throw ImageInputError("cannot open image " + quoted(read.path) + ": " + strerror(ENOENT));
  if (!S_ISREG(id.st.st_mode)) throw ImageInputError("cannot open image " + quoted(read.path) + ": not a regular file");
}

// Two writes of one file: refused, unless both write through one character device (/dev/null).
void checkTwoWrites(const PlannedWrite& a, const FileIdentity& ia, const PlannedWrite& b, const FileIdentity& ib) {
  if (!sameFile(ia, ib) || (ia.exists && S_ISCHR(ia.st.st_mode))) return;
  if (a.path == b.path)
    throw UsageError("refusing to write " + quoted(a.path) + " twice: it is " + a.what + " and " + b.what);
  throw UsageError("refusing to write " + quoted(a.path) + " and " + quoted(b.path) + ": they are one file, " +
                   a.what + " and " + b.what);
}

}  // namespace

std::string writeTarget(const std::string& path) {
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

void planSceneReads(OutputPlan& plan, const Scene& scene, const std::string& label) {
  for (size_t i = 0; i < scene.files.size(); ++i)
    plan.reads.push_back({scene.files[i], i == 0 ? "the scene file" : "a file " + label + " includes"});
  if (scene.files.empty()) plan.reads.push_back({scene.path, "the scene file"});
  for (const Material& m : scene.materials)
    if (m.texture.kind == TextureKind::Image) plan.reads.push_back({m.texture.imagePath, "an image " + label + " uses"});
}

void mergePlan(OutputPlan& plan, const OutputPlan& more) {
  plan.writes.insert(plan.writes.end(), more.writes.begin(), more.writes.end());
  plan.reads.insert(plan.reads.end(), more.reads.begin(), more.reads.end());
}

void checkPlan(const OutputPlan& plan) {
  std::vector<const PlannedWrite*> writes;
  std::vector<FileIdentity> writeIds;
  for (const PlannedWrite& w : plan.writes)
    if (w.path != "-") writes.push_back(&w), writeIds.push_back(identify(w.path));
  std::vector<FileIdentity> readIds;
  for (const PlannedRead& r : plan.reads) readIds.push_back(identify(r.path));
  for (size_t i = 0; i < writes.size(); ++i)
    for (size_t j = 0; j < plan.reads.size(); ++j)
      if (sameFile(writeIds[i], readIds[j]))
        throw UsageError("refusing to write " + quoted(writes[i]->path) + ": it is " + plan.reads[j].what + " (" +
                         quoted(plan.reads[j].path) + ")");
  for (size_t i = 0; i < writes.size(); ++i)
    for (size_t j = i + 1; j < writes.size(); ++j) checkTwoWrites(*writes[i], writeIds[i], *writes[j], writeIds[j]);
  for (size_t i = 0; i < writes.size(); ++i) {
    checkBeside(*writes[i]);
    checkWritable(*writes[i], writeIds[i]);
  }
  for (size_t j = 0; j < plan.reads.size(); ++j) checkRead(plan.reads[j], readIds[j]);
}
