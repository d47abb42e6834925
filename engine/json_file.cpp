#include "json_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.h"

namespace beverloo {

nlohmann::json read_json_file(const std::string& path, std::string* text) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw ConfigError(path, "cannot read: no such file");
  if (!fs::is_regular_file(st)) throw ConfigError(path, "is not a regular file (a directory, FIFO or device)");
  const auto size = fs::file_size(path, ec);
  if (ec) throw ConfigError(path, "cannot read: " + ec.message());
  if (size > kMaxJsonFileBytes)
    throw ConfigError(path, "is " + std::to_string(size) + " bytes, more than the limit of " +
                                std::to_string(kMaxJsonFileBytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot read the file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  nlohmann::json j;
  try {
    // the callback sees every nesting level while parsing, before a deep tree exists
    j = nlohmann::json::parse(s, [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
      if (depth > kMaxJsonDepth)
        throw ConfigError("", "nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      return true;
    });
  } catch (const ConfigError& e) {
    throw ConfigError(path, std::string(e.what()).substr(2));
  } catch (const nlohmann::json::out_of_range& e) {
    throw ConfigError(path, std::string("a number does not fit a double: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(path, std::string("is not valid JSON: ") + e.what());
  }
  if (text) *text = s;
  return j;
}

}  // namespace beverloo
