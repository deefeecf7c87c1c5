// Input files (input_file.h): a FIFO or device is refused before a byte is read (never a wait),
// and a whole-file read is bounded by its size before it starts and while it runs.
#include "input_file.h"
#include "support/files.h"

#include <gtest/gtest.h>

#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(InputFile, AFifoIsRefusedAtOnceNotWaitedOn) {
  fs::path dir = freshTempDir("input_file_fifo");
  ASSERT_EQ(mkfifo((dir / "a.png").c_str(), 0600), 0);
  std::string why;
  EXPECT_EQ(openRegularFile((dir / "a.png").string(), &why), -1);
  EXPECT_EQ(why, "not a regular file");
  EXPECT_EQ(openRegularStream("/dev/zero", &why), nullptr);
  EXPECT_EQ(why, "not a regular file");
  EXPECT_EQ(openRegularFile((dir / "none").string(), &why), -1);
  EXPECT_EQ(why, "No such file or directory");
  writeFile(dir / "b.png", "x");
  const int fd = openRegularFile((dir / "b.png").string(), &why);
  EXPECT_GE(fd, 0);
  EXPECT_EQ(fcntl(fd, F_GETFL) & O_NONBLOCK, 0);
  close(fd);
}

TEST(InputFile, AWholeReadIsBoundedBeforeItStarts) {
  fs::path dir = freshTempDir("input_file_bound");
  writeFile(dir / "s.cfg", std::string(1000, 'x'));
  std::string text, why;
  uint64_t size = 0;
  EXPECT_EQ(readWholeFile((dir / "s.cfg").string(), 1000, &text, &why, &size), ReadStatus::Read);
  EXPECT_EQ(text, std::string(1000, 'x'));
  text.clear();
  EXPECT_EQ(readWholeFile((dir / "s.cfg").string(), 999, &text, &why, &size), ReadStatus::TooLarge);
  EXPECT_EQ(size, 1000u);
  EXPECT_TRUE(text.empty());
  // A sparse file of 20 GB is judged by its size, not read.
  const int fd = open((dir / "sparse.cfg").c_str(), O_CREAT | O_WRONLY, 0600);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(ftruncate(fd, off_t(20) << 30), 0);
  close(fd);
  EXPECT_EQ(readWholeFile((dir / "sparse.cfg").string(), uint64_t(256) << 20, &text, &why, &size),
            ReadStatus::TooLarge);
  EXPECT_EQ(size, uint64_t(20) << 30);
  EXPECT_EQ(readWholeFile((dir / "none.cfg").string(), 10, &text, &why, &size), ReadStatus::CannotOpen);
}
