// Crash-safe writes (core/atomic_file.h): a file written under a temporary name is either
// committed whole or removed; a write that fails as on a full disk leaves nothing behind.
#include "core/atomic_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"

namespace beverloo {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const char* name) {
  const fs::path d = fs::temp_directory_path() / (std::string("beverloo-atomic-") + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(PendingFile, IsRemovedUnlessCommitted) {
  const fs::path d = fresh_dir("pending");
  const std::string target = (d / "result.h5").string();
  {
    PendingFile f(target);
    std::ofstream(f.path()) << "half of a result";
    // an exception here (a full disk, a bug) unwinds without commit()
  }
  EXPECT_FALSE(fs::exists(target + ".tmp"));
  EXPECT_FALSE(fs::exists(target));
  {
    PendingFile f(target);
    std::ofstream(f.path()) << "a whole result";
    f.commit();
  }
  EXPECT_TRUE(fs::exists(target));
  EXPECT_FALSE(fs::exists(target + ".tmp"));
  fs::remove_all(d);
}

TEST(WriteTextAtomically, AWriteThatFailsAsOnAFullDiskLeavesTheOldFileAndNoTemporary) {
  const fs::path d = fresh_dir("full");
  const std::string target = (d / "summary.json").string();
  write_text_atomically(target, "old");
  // a file size limit makes the write fail with EFBIG, as a full disk fails with ENOSPC
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  auto previous = signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  EXPECT_THROW(write_text_atomically(target, std::string(1 << 20, 'x')), IoError);
  setrlimit(RLIMIT_FSIZE, &old);
  signal(SIGXFSZ, previous);
  EXPECT_FALSE(fs::exists(target + ".tmp")) << "a failed write left its temporary file";
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
  fs::remove_all(d);
}

}  // namespace
}  // namespace beverloo
