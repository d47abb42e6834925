#pragma once
/// \file atomic_file.h
/// \brief Crash-safe file writes: a crash leaves either the old or the new file, never a torn one.
#include <string>

namespace beverloo {

/// Commits a file written to tmp_path: fsync it, rename it over path, fsync the directory.
/// Throws IoError.
void commit_atomically(const std::string& tmp_path, const std::string& path);
/// Writes text to path atomically (through path + ".tmp"). Throws IoError.
void write_text_atomically(const std::string& path, const std::string& text);

/// A file being written under a temporary name (target + ".tmp"): removed unless committed,
/// so that a failure on the way (a full disk, an exception) leaves no partial or 0-byte file
/// behind; commit() renames it over the target as commit_atomically() does.
class PendingFile {
 public:
  explicit PendingFile(const std::string& target) : tmp_(target + ".tmp"), target_(target) {}
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  ~PendingFile();
  const std::string& path() const { return tmp_; }
  void commit();

 private:
  std::string tmp_, target_;
  bool committed_ = false;
};

}  // namespace beverloo
