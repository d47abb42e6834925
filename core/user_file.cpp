#include "user_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "errors.h"

namespace beverloo {

std::string too_large(std::size_t bytes, std::size_t max_bytes) {
  return "is " + std::to_string(bytes) + " bytes, more than the limit of " + std::to_string(max_bytes);
}

std::string read_user_file(const std::string& path, std::size_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw ConfigError(path, "cannot read: no such file");
  if (!fs::is_regular_file(st)) throw ConfigError(path, "is not a regular file (a directory, FIFO or device)");
  const auto size = fs::file_size(path, ec);
  if (ec) throw ConfigError(path, "cannot read: " + ec.message());
  if (size > max_bytes) throw ConfigError(path, too_large(size, max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot read the file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace beverloo
