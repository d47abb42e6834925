// Where a DP step's time goes, term by term: a flowing state of a bench case (warmed up as
// `beverloo bench` does), then each force term's accumulate() timed alone over many repeats
// (the list built once: the terms' own cost), the list's update, and a whole step. Printed per
// term: ns per vertex and its share of the sum of the terms.
// Usage: dp_term_costs '<job json>' warmup_t0 repeats
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "engine/config.h"
#include "engine/forces/force_term.h"
#include "engine/dp/dp_system.h"
#include "engine/protocol/hopper_run.h"

using namespace beverloo;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s '<job json>' warmup_t0 repeats\n", argv[0]);
    return 2;
  }
  SimConfig c = SimConfig::from_json(nlohmann::json::parse(argv[1]));
  const double warmup = std::atof(argv[2]);
  const int repeats = std::atoi(argv[3]);
  HopperRun<2> run(c, RunOptions{});
  run.prepare();
  const double dt = run.time_step().dt;
  run.advance(static_cast<std::int64_t>(warmup / dt));
  HopperModel<2>& model = run.model();
  ParticleState<2>& s = model.term_state(run.state());
  const int n = s.size();
  std::printf("%d vertices, dt %.3g\n", n, dt);
  if (DpSystem* dp = run.dp())
    std::printf("vertex list: %.2f pairs per vertex (skin %.3g)\n", double(dp->forces().list().pairs()) / n,
                dp->forces().list().skin());
  VecArray<2> f(n, Vec<2>::Zero());
  double total = 0;
  std::vector<std::pair<std::string, double>> rows;
  for (ForceTerm<2>* term : model.terms()) {
    term->accumulate(s, f);  // warm the caches
    const auto t0 = Clock::now();
    for (int r = 0; r < repeats; ++r) term->accumulate(s, f);
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / repeats / n;
    rows.emplace_back(std::string(term->name()), ns);
    total += ns;
  }
  for (const auto& [name, ns] : rows) std::printf("%-22s %7.2f ns/vertex  %5.1f %%\n", name.c_str(), ns, 100 * ns / total);
  std::printf("%-22s %7.2f ns/vertex\n", "sum of the terms", total);
  const auto t0 = Clock::now();
  const int steps = repeats;
  run.advance(steps);
  const double step_ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / steps / n;
  std::printf("%-22s %7.2f ns/vertex (%.3g vertex-steps/s)\n", "a whole step", step_ns, 1e9 / step_ns);
  return 0;
}
