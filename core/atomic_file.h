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

}  // namespace beverloo
