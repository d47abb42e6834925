#pragma once
/// \file disk_space.h
/// \brief Whether a failed write failed because the file system is full. A full disk is not the
/// job's fault and no retry fixes it until someone makes room, so the coordinator neither
/// charges the job's retry budget nor goes on claiming jobs (docs/database.md, failure classes).
#include <cstdint>
#include <string>
#include <string_view>

namespace beverloo {

/// Below this many bytes available to us, a file system counts as full: a write that failed
/// there failed for want of room (a checkpoint of a small job is tens of kilobytes; the free
/// space after such a failure is less than what the write needed).
inline constexpr std::uint64_t kFullBelowBytes = std::uint64_t{1} << 20;

/// True if `message` says there is no space (strerror(ENOSPC), which our file writes and HDF5
/// flushes append; SQLite's "database or disk is full"), or the file system holding `path` (or
/// its nearest existing parent) has less than kFullBelowBytes available.
bool no_space_left(const std::string& path, std::string_view message);
/// True if the file system holding `path` (or its nearest existing parent) has less than
/// kFullBelowBytes available now (false when that cannot be told).
bool file_system_full(const std::string& path);

}  // namespace beverloo
