#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "errors.h"

namespace beverloo {
namespace {
void fsync_path(const std::string& path, bool directory) {
  const int fd = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
  if (fd < 0) throw IoError("cannot open " + path + " to sync: " + std::strerror(errno));
  const int rc = ::fsync(fd);
  ::close(fd);
  if (rc != 0) throw IoError("fsync " + path + ": " + std::strerror(errno));
}
}  // namespace

void commit_atomically(const std::string& tmp_path, const std::string& path) {
  fsync_path(tmp_path, false);
  if (std::rename(tmp_path.c_str(), path.c_str()) != 0)
    throw IoError("rename " + tmp_path + " -> " + path + ": " + std::strerror(errno));
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  fsync_path(dir.empty() ? "." : dir.string(), true);
}

PendingFile::~PendingFile() {
  if (!committed_) ::unlink(tmp_.c_str());  // nothing to say if it is already gone
}

void PendingFile::commit() {
  commit_atomically(tmp_, target_);
  committed_ = true;
}

void write_text_atomically(const std::string& path, const std::string& text) {
  PendingFile file(path);
  {
    std::ofstream out(file.path(), std::ios::binary | std::ios::trunc);
    if (!out) throw IoError("cannot write " + file.path());
    out << text;
    out.flush();
    if (!out) throw IoError("write failed: " + file.path() + " (a full disk?)");
  }
  file.commit();
}

}  // namespace beverloo
