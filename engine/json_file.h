#pragma once
/// \file json_file.h
/// \brief Reading a user's JSON file (job or sweep) with its limits checked before memory is
/// used: only a regular file (a FIFO or a device would block or never end), at most
/// kMaxJsonFileBytes, nesting at most kMaxJsonDepth deep (a deeper document would exhaust the
/// stack when it is destroyed), numbers that fit a double. Every failure is a ConfigError
/// naming the file and the reason.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace beverloo {

inline constexpr std::size_t kMaxJsonFileBytes = 16u << 20;  ///< 16 MiB
inline constexpr int kMaxJsonDepth = 64;

/// Reads and parses path; the file's text goes to *text if given. Throws ConfigError(path, ...).
nlohmann::json read_json_file(const std::string& path, std::string* text = nullptr);

/// The same rules for text already in memory (the fuzzers' entry); `path` names it in messages.
nlohmann::json parse_json_text(const std::string& text, const std::string& path);

}  // namespace beverloo
