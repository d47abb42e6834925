// libFuzzer target: a job file's text through everything `simulate` does before it runs
// (engine/json_file limits, SimConfig parsing and validation, the time step, the memory check).
// Every input must end in a value or a ConfigError; anything else (another exception, a
// sanitizer report, a hang, memory beyond -rss_limit_mb) is a finding. tests/fuzz/run_fuzzers.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/config.h"
#include "engine/json_file.h"
#include "engine/models/model_time_step.h"
#include "engine/protocol/memory_estimate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace beverloo;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const SimConfig c = SimConfig::from_json(parse_json_text(text, "fuzz.json"));
    (void)choose_time_step(c);
    (void)estimated_memory_bytes(c);
    (void)c.to_json().dump();
  } catch (const ConfigError&) {
  }
  return 0;
}
