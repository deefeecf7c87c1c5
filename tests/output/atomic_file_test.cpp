// writeFileAtomic and outputClash (host/output/atomic_file.h) on real files, device nodes and FIFOs in
// a temporary directory. Device nodes need root (mknod); those tests skip without it.
#include "atomic_file.h"
#include "parser.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

std::vector<uint8_t> someBytes(size_t n) {
  std::vector<uint8_t> bytes(n);
  for (size_t i = 0; i < n; ++i) bytes[i] = uint8_t(i * 31 + 7);
  return bytes;
}


// The message of the std::runtime_error writeFileAtomic throws; empty if it does not throw.
std::string writeError(const fs::path& path, const std::vector<uint8_t>& bytes) {
  try {
    writeFileAtomic(path.string(), bytes);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// A character device node like /dev/null (1, 3) or /dev/full (1, 7), or skip.
#define MAKE_CHAR_DEVICE(path, minor)                                                       \
  if (mknod((path).c_str(), S_IFCHR | 0666, makedev(1, (minor))) != 0)                      \
  GTEST_SKIP() << "cannot mknod " << (path) << " (" << strerror(errno) << "): not root?"

TEST(AtomicFile, WritesThroughToANullDeviceAndKeepsIt) {
  fs::path dir = freshTempDir("output_file_null");
  fs::path null = dir / "null";
  MAKE_CHAR_DEVICE(null, 3);
  EXPECT_EQ(writeError(null, someBytes(1000)), "");
  EXPECT_TRUE(fs::is_character_file(null));
  EXPECT_EQ(entryCount(dir), 1u);  // no temporary file, no PNG beside it
}

TEST(AtomicFile, AFullDeviceIsAWriteErrorAndStaysADevice) {
  fs::path dir = freshTempDir("output_file_full");
  fs::path full = dir / "full";
  MAKE_CHAR_DEVICE(full, 7);
  EXPECT_EQ(writeError(full, someBytes(1000)), "cannot write '" + full.string() + "': No space left on device");
  EXPECT_TRUE(fs::is_character_file(full));
  EXPECT_EQ(entryCount(dir), 1u);
}

TEST(AtomicFile, AFifoWithNoReaderIsAnErrorNotAWait) {
  fs::path dir = freshTempDir("output_file_fifo");
  fs::path fifo = dir / "fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(writeError(fifo, someBytes(100)), "cannot write '" + fifo.string() + "': no process is reading it");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(AtomicFile, AFifoWithAReaderGetsTheBytes) {
  fs::path dir = freshTempDir("output_file_fifo_reader");
  fs::path fifo = dir / "fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  int reader = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  std::vector<uint8_t> bytes = someBytes(1000);  // fits in the pipe's buffer
  EXPECT_EQ(writeError(fifo, bytes), "");
  std::vector<uint8_t> got(2000);
  ssize_t n = read(reader, got.data(), got.size());
  close(reader);
  got.resize(size_t(std::max<ssize_t>(n, 0)));
  EXPECT_EQ(got, bytes);
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(AtomicFile, ASymlinkIsFollowedAndItsTargetReplaced) {
  fs::path dir = freshTempDir("output_file_symlink");
  fs::create_directories(dir / "real");
  writeFile(dir / "real" / "a.png", "old");
  fs::create_symlink("real/a.png", dir / "link.png");
  std::vector<uint8_t> bytes = someBytes(50);
  EXPECT_EQ(writeError(dir / "link.png", bytes), "");
  EXPECT_TRUE(fs::is_symlink(dir / "link.png"));
  EXPECT_EQ(readFile(dir / "real" / "a.png"), std::string(bytes.begin(), bytes.end()));
  EXPECT_EQ(entryCount(dir / "real"), 1u);
}

TEST(AtomicFile, AnExistingFileKeepsItsModeAndANewOneFollowsTheUmask) {
  fs::path dir = freshTempDir("output_file_mode");
  writeFile(dir / "private.png", "old");
  ASSERT_EQ(chmod((dir / "private.png").c_str(), 0600), 0);
  EXPECT_EQ(writeError(dir / "private.png", someBytes(10)), "");
  struct stat st;
  ASSERT_EQ(stat((dir / "private.png").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);

  mode_t mask = umask(027);
  EXPECT_EQ(writeError(dir / "new.png", someBytes(10)), "");
  umask(mask);
  ASSERT_EQ(stat((dir / "new.png").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u);
}

TEST(AtomicFile, NamesUpTo255BytesAreWritten) {
  fs::path dir = freshTempDir("output_file_long");
  for (size_t length : {245, 250, 255}) {
    std::string name = std::string(length - 4, 'n') + ".png";
    std::vector<uint8_t> bytes = someBytes(length);
    EXPECT_EQ(writeError(dir / name, bytes), "") << length;
    EXPECT_EQ(readFile(dir / name), std::string(bytes.begin(), bytes.end()));
  }
  EXPECT_EQ(entryCount(dir), 3u);
}

TEST(AtomicFile, TheTempNameFitsTheLimitAndCutsNoCharacter) {
  EXPECT_EQ(tempTemplate("dir/a.png", 255), "dir/a.png.tmp-XXXXXX");
  std::string name = std::string(251, 'a') + ".png";
  std::string tmp = tempTemplate("/x/" + name, 255);
  EXPECT_EQ(tmp, "/x/" + std::string(244, 'a') + ".tmp-XXXXXX");
  std::string utf8;  // "é" is two bytes: 122 of them, then ".png" (248 bytes)
  for (int i = 0; i < 122; ++i) utf8 += "\xc3\xa9";
  tmp = tempTemplate(utf8 + ".png", 255);  // 244 bytes kept: whole characters
  EXPECT_EQ(tmp, utf8 + ".tmp-XXXXXX");
  tmp = tempTemplate(utf8 + ".png", 254);  // 243 bytes would split the last one: 242
  EXPECT_EQ(tmp, utf8.substr(0, 242) + ".tmp-XXXXXX");
}

// Forks a child that writes `bytes` to `path` and is stopped in the middle by the test hook,
// sends it `sig`, and returns its wait status.
// With `named`, the output takes the named temporary file (as where O_TMPFILE is refused);
// `*entriesSeen` is what the directory held while the child was stopped.
int signalInTheMiddleOfAWrite(const fs::path& path, int sig, bool named, size_t* entriesSeen) {
  pid_t child = fork();
  if (child == 0) {
    signal(sig, SIG_DFL);
    setenv("RAYTEX_TEST_PAUSE_IN_WRITE", "1", 1);
    if (named) setenv("RAYTEX_TEST_NAMED_TEMP", "1", 1);
    try {
      writeFileAtomic(path.string(), someBytes(100000));
    } catch (...) {
    }
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, WUNTRACED);
  *entriesSeen = WIFSTOPPED(status) ? entryCount(path.parent_path()) : 0;
  if (!WIFSTOPPED(status)) return status;  // it ended without stopping: no test hook
  kill(child, sig);
  kill(child, SIGCONT);
  waitpid(child, &status, 0);
  return status;
}

// Every signal whose default action ends the process, in the middle of a write: the old file
// stays and nothing else is left, whether the output has no name until commit (O_TMPFILE: no
// file to see while it is written) or a named temporary (seen, then removed by the handler).
TEST(AtomicFile, ASignalDuringTheWriteLeavesNothingAndEndsWithTheSignal) {
  for (bool named : {false, true})
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGPIPE, SIGXCPU, SIGVTALRM,
                    SIGPROF}) {
      fs::path dir = freshTempDir("output_file_signal");
      writeFile(dir / "out.png", "old");
      size_t seen = 0;
      int status = signalInTheMiddleOfAWrite(dir / "out.png", sig, named, &seen);
      EXPECT_EQ(seen, named ? 2u : 1u) << strsignal(sig) << (named ? ", named" : "");
      EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << strsignal(sig) << ": status " << status;
      EXPECT_EQ(entryCount(dir), 1u) << strsignal(sig) << (named ? ", named" : "");
      EXPECT_EQ(readFile(dir / "out.png"), "old") << strsignal(sig);
    }
}

TEST(AtomicFile, WithdrawRemovesWhatCommitPutInPlace) {
  fs::path dir = freshTempDir("output_file_withdraw");
  for (bool named : {false, true}) {
    if (named) setenv("RAYTEX_TEST_NAMED_TEMP", "1", 1);
    AtomicFile file((dir / "a.png").string());
    file.write(someBytes(10));
    file.commit();
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    file.withdraw();
    EXPECT_FALSE(fs::exists(dir / "a.png"));
    EXPECT_EQ(entryCount(dir), 0u);
    unsetenv("RAYTEX_TEST_NAMED_TEMP");
  }
}

TEST(AtomicFile, AFileSizeLimitIsAWriteErrorThatLeavesNoTempFile) {
  fs::path dir = freshTempDir("output_file_fsize");
  writeFile(dir / "out.png", "old");
  pid_t child = fork();
  if (child == 0) {
    signal(SIGXFSZ, SIG_DFL);
    struct rlimit limit = {1024, 1024};
    setrlimit(RLIMIT_FSIZE, &limit);
    std::string error = writeError(dir / "out.png", someBytes(100000));
    _exit(error == "cannot write '" + (dir / "out.png").string() + "': File too large" ? 0 : 3);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  EXPECT_EQ(entryCount(dir), 1u);
  EXPECT_EQ(readFile(dir / "out.png"), "old");
}

TEST(Errors, ALocatedErrorIsPrintedAsItIsAndAnyOtherBehindTheProgramName) {
  const SceneError scene(FileLoc{"s.cfg", 3, 7}, "unknown key 'radiuss'");
  EXPECT_EQ(scene.kind, ErrorKind::Scene);
  EXPECT_EQ(errorLine(scene), "s.cfg:3:7: unknown key 'radiuss'");
  const ImageInputError image(FileLoc{"s.cfg", 1, 39}, "cannot open image 'e.jpg': not a regular file");
  EXPECT_EQ(image.kind, ErrorKind::ImageInput);
  EXPECT_EQ(errorLine(image), "s.cfg:1:39: cannot open image 'e.jpg': not a regular file");
  EXPECT_EQ(errorLine(ImageInputError("'x.png' is not a PNG or JPEG file")), "raytex: 'x.png' is not a PNG or JPEG file");
  EXPECT_EQ(errorLine(VulkanError("vkFoo failed")), "raytex: vkFoo failed");
  EXPECT_EQ(VulkanError("x").kind, ErrorKind::Device);
  EXPECT_EQ(IoError("x").kind, ErrorKind::Io);
  EXPECT_EQ(UsageError("x").kind, ErrorKind::Usage);
  EXPECT_EQ(errorLine(SceneError(FileLoc{"missing.cfg", 0, 0}, "cannot open")), "missing.cfg: cannot open");
}

TEST(Errors, AFailedWriteToTheOutputStreamIsAnIoError) {
  fs::path dir = freshTempDir("output_file_stdout");
  fs::path full = dir / "full";
  MAKE_CHAR_DEVICE(full, 7);
  FILE* out = fopen(full.c_str(), "w");
  ASSERT_NE(out, nullptr);
  fputs("usage: ...\n", out);
  try {
    finishStdout(out);
    ADD_FAILURE() << "a write to /dev/full passed";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "cannot write to standard output: No space left on device");
  }
  fclose(out);
  FILE* fine = fopen((dir / "fine").c_str(), "w");
  ASSERT_NE(fine, nullptr);
  fputs("ok\n", fine);
  EXPECT_NO_THROW(finishStdout(fine));
  fclose(fine);
}

}  // namespace
