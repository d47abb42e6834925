// libFuzzer target: a draining-hopper data file's text through `experiment import`'s reading,
// unit resolution and per-run fits (everything but the database). Every input must end in a
// fit or a ConfigError. tests/fuzz/run_fuzzers.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "engine/protocol/drain_fit.h"
#include "orchestrator/experiment/experiment_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace beverloo;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const experiment::ExperimentFile f = experiment::parse_csv_text(text, "fuzz.csv");
    const experiment::Resolved u = experiment::resolve_units(f, {});
    for (const experiment::RunData& r : f.runs) (void)fit_drain(r.exit_t_s, r.n_initial, 10, 3);
    (void)u;
  } catch (const ConfigError&) {
  }
  return 0;
}
