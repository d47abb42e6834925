// libFuzzer target: a sweep file's text through parsing, expansion (with its size limit) and
// the validation of every job it makes, as `sweep check` does. Every input must end in a
// sweep or a SweepError/ConfigError. tests/fuzz/run_fuzzers.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/json_file.h"
#include "orchestrator/sweep/sweep.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace beverloo;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Sweep s = Sweep::parse(parse_json_text(text, "fuzz.json"), "fuzz");
    (void)s.expand();
  } catch (const SweepError&) {
  } catch (const ConfigError&) {
  }
  return 0;
}
