// AtomicFile: symlinks, file modes, FIFOs (as devices are written), batches of outputs, and
// signals.
#include "hexadapt/io/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "hexadapt/io/temp_files.h"

namespace hexadapt::io {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hexadapt_atomic_file_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string content(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int entries(const fs::path& dir) {
  return static_cast<int>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, WritesThroughASymlinkToItsTarget) {
  const fs::path dir = scratch("symlink");
  fs::create_directories(dir / "real");
  std::ofstream(dir / "real" / "target.txt") << "old";
  fs::create_symlink("real/target.txt", dir / "link.txt");
  write_file_atomically((dir / "link.txt").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(content(dir / "real" / "target.txt"), "new");
  EXPECT_EQ(entries(dir / "real"), 1);  // no temporary file left beside the target
}

TEST(AtomicFile, KeepsTheModeOfTheFileItReplaces) {
  const fs::path dir = scratch("mode");
  const fs::path p = dir / "out.txt";
  std::ofstream(p) << "old";
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write);
  write_file_atomically(p.string(), "new");
  EXPECT_EQ(content(p), "new");
  EXPECT_EQ(fs::status(p).permissions(), fs::perms::owner_read | fs::perms::owner_write);
}

TEST(AtomicFile, WritesAFifoDirectly) {
  const fs::path dir = scratch("fifo");
  const fs::path p = dir / "pipe";
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  const int reader = ::open(p.c_str(), O_RDONLY | O_NONBLOCK);  // so that the writer opens
  ASSERT_GE(reader, 0);
  write_file_atomically(p.string(), "through the pipe");
  char buf[64] = {};
  const ssize_t n = ::read(reader, buf, sizeof buf);
  ::close(reader);
  EXPECT_TRUE(fs::is_fifo(p));
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe");
}

TEST(OutputBatch, RenamesAllOutputsOnlyOnCommit) {
  const fs::path dir = scratch("batch");
  {
    OutputBatch batch;
    write_file_atomically((dir / "a.txt").string(), "a");
    write_file_atomically((dir / "b.txt").string(), "b");
    EXPECT_FALSE(fs::exists(dir / "a.txt"));
    batch.commit();
  }
  EXPECT_EQ(content(dir / "a.txt"), "a");
  EXPECT_EQ(content(dir / "b.txt"), "b");
  EXPECT_EQ(entries(dir), 2);
}

TEST(OutputBatch, WritesNothingWithoutCommit) {
  const fs::path dir = scratch("batch_abandoned");
  std::ofstream(dir / "a.txt") << "old";
  {
    OutputBatch batch;
    write_file_atomically((dir / "a.txt").string(), "new");
    write_file_atomically((dir / "b.txt").string(), "b");
  }
  EXPECT_EQ(content(dir / "a.txt"), "old");
  EXPECT_EQ(entries(dir), 1);
}

TEST(TempFiles, ASignalDuringAWriteRemovesTheTemporaryFile) {
  const fs::path dir = scratch("signal");
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      remove_temp_files_on_signals();
      AtomicFile f((dir / "out.txt").string());
      f.stream() << "partial" << std::flush;
      std::raise(sig);
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "signal " << sig;
    EXPECT_EQ(entries(dir), 0) << "signal " << sig;
  }
}

}  // namespace
}  // namespace hexadapt::io
