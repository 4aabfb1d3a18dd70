// The atomic output writer (sim/output_file.h) under a signal: a Ctrl-C that arrives while an
// output is being written takes effect once the file is complete under its final name, and
// leaves no "<file>.tmp.<pid>" behind (issue 39: a second Ctrl-C while strata-sim wrote its
// outputs left them). It lives in the trace suite, which links the simulator's I/O library.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "sim/output_file.h"
#include "test/support/test_files.h"

namespace strata::sim {
namespace {

using testing::TempDir;

std::filesystem::path temporary_of(const std::filesystem::path& file, pid_t pid) {
  std::filesystem::path tmp = file;
  tmp += ".tmp." + std::to_string(pid);
  return tmp;
}

// The writer's temporary is made a FIFO beforehand, so the write blocks until the test reads it:
// the signal is sent while the writer is certainly between its open and its rename.
TEST(OutputFile, ASignalDuringTheWriteTakesEffectAfterItAndLeavesNoTemporary) {
  TempDir dir;
  const std::filesystem::path file = dir / "out.bin";
  const std::vector<uint8_t> bytes(1 << 20, 7);  // far beyond a pipe's 64 KiB
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    signal(SIGINT, SIG_DFL);
    if (mkfifo(temporary_of(file, getpid()).c_str(), 0644) != 0) _exit(3);
    try {
      write_file_atomically(file, bytes);
    } catch (...) {
      _exit(2);
    }
    _exit(0);  // not reached with the signal held: it is delivered when the write ends
  }
  const std::filesystem::path tmp = temporary_of(file, pid);
  for (int i = 0; i < 10000 && !std::filesystem::exists(tmp); ++i) usleep(1000);
  const int fd = open(tmp.c_str(), O_RDONLY);  // returns once the writer has opened its end
  ASSERT_GE(fd, 0);
  char buf[65536];
  ssize_t n = read(fd, buf, sizeof buf);
  ASSERT_GT(n, 0);  // the writer is mid-write, blocked on the full pipe
  kill(pid, SIGINT);
  size_t total = size_t(n);
  while ((n = read(fd, buf, sizeof buf)) > 0) total += size_t(n);
  close(fd);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "status " << status;
  EXPECT_EQ(total, bytes.size()) << "the write was cut off";
  EXPECT_FALSE(std::filesystem::exists(tmp)) << "the temporary was left behind";
  EXPECT_TRUE(std::filesystem::exists(file)) << "the file never reached its final name";
}

}  // namespace
}  // namespace strata::sim
