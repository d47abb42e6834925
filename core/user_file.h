#pragma once
/// \file user_file.h
/// \brief Reading a file a user named (job, sweep, data file) with its limits checked before
/// any memory is used: it must exist, be a regular file (a FIFO or a device would block or
/// never end) and hold at most max_bytes. Every refusal is a ConfigError naming the path.
#include <cstddef>
#include <string>

namespace beverloo {

/// The whole file, or ConfigError(path, why not).
std::string read_user_file(const std::string& path, std::size_t max_bytes);

/// The limit message, for text that arrives in memory: "is N bytes, more than the limit of M".
std::string too_large(std::size_t bytes, std::size_t max_bytes);

}  // namespace beverloo
