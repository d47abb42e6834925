#include "json_file.h"

#include <set>
#include <vector>

#include "core/errors.h"
#include "core/user_file.h"

namespace beverloo {

nlohmann::json read_json_file(const std::string& path, std::string* text) {
  const std::string s = read_user_file(path, kMaxJsonFileBytes);
  nlohmann::json j = parse_json_text(s, path);
  if (text) *text = s;
  return j;
}

nlohmann::json parse_json_text(const std::string& s, const std::string& path) {
  if (s.size() > kMaxJsonFileBytes) throw ConfigError(path, too_large(s.size(), kMaxJsonFileBytes));
  nlohmann::json j;
  try {
    // The callback sees every nesting level while parsing, before a deep tree exists; and
    // every key of every object, so that a key given twice is an error naming its place (the
    // parser would keep the last one silently).
    struct Frame {
      bool array;
      std::string name;       // "sweep.union[1]"
      std::size_t index = 0;  // arrays: the next element's index
      std::set<std::string> keys;
    };
    std::vector<Frame> frames;
    std::string last_key;
    auto element_name = [&]() -> std::string {
      if (frames.empty()) return "";
      Frame& parent = frames.back();
      if (parent.array) return parent.name + "[" + std::to_string(parent.index++) + "]";
      return parent.name.empty() ? last_key : parent.name + "." + last_key;
    };
    using E = nlohmann::json::parse_event_t;
    j = nlohmann::json::parse(s, [&](int depth, E event, nlohmann::json& parsed) {
      if (depth > kMaxJsonDepth)
        throw ConfigError("", "nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      switch (event) {
        case E::object_start:
        case E::array_start: {
          std::string name = element_name();
          frames.push_back(Frame{event == E::array_start, std::move(name), 0, {}});
          break;
        }
        case E::object_end:
        case E::array_end:
          frames.pop_back();
          break;
        case E::key:
          last_key = parsed.get<std::string>();
          if (!frames.back().keys.insert(last_key).second) {
            const std::string& at = frames.back().name;
            throw ConfigError("", "the key \"" + (at.empty() ? "" : at + ".") + last_key +
                                      "\" is given twice (which one is meant?)");
          }
          break;
        case E::value:
          if (!frames.empty() && frames.back().array) ++frames.back().index;  // a scalar element
          break;
      }
      return true;
    });
  } catch (const ConfigError& e) {
    throw ConfigError(path, std::string(e.what()).substr(2));
  } catch (const nlohmann::json::out_of_range& e) {
    throw ConfigError(path, std::string("a number does not fit a double: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(path, std::string("is not valid JSON: ") + e.what());
  }
  return j;
}

}  // namespace beverloo
