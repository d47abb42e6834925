// `beverloo bench [--runs R] [--case a|b|c|d|e|f ...] [--scale S]`: the standard performance cases,
// particle-steps (SP) or vertex-steps (DP) per second, median and spread of R timed runs from the same flowing state.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "core/atomic_file.h"
#include "core/cpus.h"
#include "core/text_escape.h"
#include "engine/json_file.h"
#include "engine/models/authors_dp_set.h"
#include "engine/models/model_time_step.h"
#include "engine/parameters.h"
#include "engine/protocol/hopper_run.h"
#include "commands.h"
#include "guarded.h"
#include "core/failures.h"
#include "core/version.h"

namespace beverloo {
namespace {

/// Where the human-readable lines go: stdout, or stderr when the JSON goes to stdout (--json -).
FILE* human = stdout;

struct BenchCase {
  std::string id, description;
  SimConfig config;
  double warmup_time;     ///< t0 of flow before timing (SP: the pile is flowing; DP: 0.3 t0, the
                          ///< column falling and landing: at dt ~ 6e-6 a flowing state costs minutes)
  std::int64_t steps;     ///< timed steps per run
};

std::vector<BenchCase> standard_cases(double scale, double skin) {
  auto base = [skin](int dim, int N, double zeta, double mu) {
    SimConfig c;
    c.dimension = dim;
    c.N = N;
    c.w = 6;
    c.E_sp = 100;
    c.zeta = zeta;
    c.mu = mu;
    c.seed = 1;
    if (skin > 0) c.skin = skin;
    c.resolve_and_validate();
    return c;
  };
  // the lambda axis's limits at scale 1: mu = 10 sqrt 10, zeta = 1 / sqrt 10
  const double mu_f = derived::on_lambda_axis(0, 1).mu, zeta_d = derived::on_lambda_axis(INFINITY, 1).zeta;
  auto dp = [&](const std::string& model) {
    SimConfig c;
    c.model = model;
    c.N = 1600;
    c.w = 6;
    c.dp.K_l = 10;
    c.dp.K_b = 0.1;
    c.zeta = zeta_d;
    c.mu = 0;
    c.seed = 1;
    if (skin > 0) c.skin = skin;
    c.resolve_and_validate();
    return c;
  };
  // the smooth DP contact of the authors' code (docs/authors-model.md), with the wall softened
  // too: at E_w = 1e4 the vertex wall, not the contact, sets the time step
  auto authors_dp = [&] {
    SimConfig c = dp("dp_smooth");
    c.dp.E_c = 115.7;
    c.dp.contact_width = 0.2;
    c.E_w = 100;
    c.resolve_and_validate();
    return c;
  };
  // The DP set of the authors' code, corrected (docs/authors-model.md, section 3: kl = 1,
  // ka = 100, kb = 0.01, kint = 10, cutoff 0.2, vertex wall l0 wide), at the paper's size with
  // the code's drag (b = 0.1) and reinjection: the job a user plans a DP campaign with.
  auto authors_dp_1600 = [&](const std::string& model) {
    SimConfig c;
    c.model = model;
    c.N = 1600;
    c.W = 50;
    c.w = 6;
    c.zeta = 0;
    c.mu = 0;
    c.drag_rate = 1.95959;
    c.reinjection.rule = "lanes";
    c.reinjection.drop_depth_diameters = 2.5;
    use_authors_dp_set(c);
    c.seed = 1;
    if (skin > 0) c.skin = skin;
    c.resolve_and_validate();
    return c;
  };
  return {
      {"a", "2D SP N=1600 w=6 E_sp=100 friction only (mu=10 sqrt 10)", base(2, 1600, 0, mu_f), 30,
       std::llround(20000 * scale)},
      {"b", "2D SP N=1600 w=6 E_sp=100 drag only (zeta=1/sqrt 10)", base(2, 1600, zeta_d, 0), 30,
       std::llround(20000 * scale)},
      {"c", "3D SP N=6400 w=6 E_sp=100 friction only (mu=10 sqrt 10)", base(3, 6400, 0, mu_f), 10,
       std::llround(4000 * scale)},
      {"d", "2D smooth DP N=1600 N_v=16 K_l=10 K_b=0.1 E_c=1e4 w=6 drag only", dp("dp_smooth"), 0.3,
       std::llround(2000 * scale)},
      {"e", "2D rough DP N=1600 N_v=16 K_l=10 K_b=0.1 E_c=1e4 w=6 drag only", dp("dp_rough"), 0.3,
       std::llround(2000 * scale)},
      {"f", "2D smooth DP as (d) with the authors' contact E_c=115.7 width 0.2 l0, E_w=1e2", authors_dp(), 0.3,
       std::llround(2000 * scale)},
      {"g", "2D smooth DP N=1600 W=50 the authors' corrected set, drag_rate 1.96, lanes", authors_dp_1600("dp_smooth"),
       0.3, std::llround(2000 * scale)},
      {"h", "2D rough DP N=1600 W=50 the authors' corrected set, drag_rate 1.96, lanes", authors_dp_1600("dp_rough"),
       0.3, std::llround(2000 * scale)},
  };
}

/// One case's measurement (bench --json: docs/cli.md).
struct CaseResult {
  std::string id, description, unit;
  double median = 0, min = 0, max = 0, dt = 0, builds_per_kstep = 0, skin = 0;
  int runs = 0;
  std::int64_t steps = 0, points = 0;
  int threads = 1;
  std::string dt_limit;          ///< the term that sets dt
  double t0_per_cpu_minute = 0;  ///< t0 of flow one core simulates per minute at the median rate
};

template <int D>
CaseResult run_case(const BenchCase& bc, int runs, int threads) {
  RunOptions options;
  options.threads = threads;
  options.adapt_threads = false;  // the bench times the count it was given
  HopperRun<D> warm(bc.config, options);
  warm.prepare();
  warm.advance(std::llround(bc.warmup_time / warm.time_step().dt));
  std::vector<double> rates;
  double builds_per_kstep = 0;
  for (int r = 0; r < runs; ++r) {
    HopperRun<D> run = HopperRun<D>(bc.config, options);
    run.prepare();
    // every timed run starts from the same warmed-up state
    run.copy_state_from(warm);
    const auto t0 = std::chrono::steady_clock::now();
    const std::int64_t builds_before = run.neighbor_builds();
    run.advance(bc.steps);
    builds_per_kstep = 1000.0 * (run.neighbor_builds() - builds_before) / bc.steps;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rates.push_back(bc.steps * double(run.moving_points()) / s);
  }
  std::sort(rates.begin(), rates.end());
  const double median = rates[rates.size() / 2];
  CaseResult out{bc.id, bc.description, bc.config.is_dp() ? "vertex-steps/s" : "particle-steps/s", median, rates.front(),
                 rates.back(), warm.time_step().dt, builds_per_kstep, bc.config.skin, runs, bc.steps, warm.moving_points(),
                 threads, "", 0.0};
  out.dt_limit = warm.time_step().limiting_term;
  // steps per second x dt = t0 per second, over the threads: per CPU
  out.t0_per_cpu_minute = 60 * median / double(out.points) * out.dt / (out.threads > 0 ? out.threads : 1);
  std::fprintf(human, "%-2s %-58s skin %.2f builds/1000 steps %.1f  median %.3g  min %.3g  max %.3g %s  (%d runs x %lld steps, dt %.3g, %d thread%s)\n",
              out.id.c_str(), out.description.c_str(), out.skin, out.builds_per_kstep, out.median, out.min, out.max,
              out.unit.c_str(), out.runs, static_cast<long long>(out.steps), out.dt, out.threads, out.threads == 1 ? "" : "s");
  std::fprintf(human, "   dt limited by %s; %.3g t0 of flow per CPU-minute\n", out.dt_limit.c_str(), out.t0_per_cpu_minute);
  std::fflush(human);
  return out;
}

nlohmann::json to_json(const CaseResult& r) {
  return {{"id", r.id}, {"description", r.description}, {"unit", r.unit}, {"median", r.median}, {"min", r.min},
          {"max", r.max}, {"runs", r.runs}, {"steps_per_run", r.steps}, {"moving_points", r.points}, {"dt", r.dt},
          {"skin", r.skin}, {"list_builds_per_1000_steps", r.builds_per_kstep}, {"threads", r.threads},
          {"dt_limited_by", r.dt_limit}, {"t0_per_cpu_minute", r.t0_per_cpu_minute}};
}

/// The medians of an earlier `bench --json` by case id; ConfigError naming the file if unreadable.
std::map<std::string, double> read_baseline(const std::string& path) {
  const nlohmann::json j = read_json_file(path);
  std::map<std::string, double> medians;
  if (!j.is_object() || !j.contains("cases") || !j["cases"].is_array())
    throw ConfigError(path, "is not the output of `beverloo bench --json` (no \"cases\" list)");
  for (const auto& c : j["cases"]) {
    if (!c.is_object() || !c.contains("id") || !c.contains("median") || !c["id"].is_string() || !c["median"].is_number())
      throw ConfigError(path, "a case lacks its \"id\" or \"median\"");
    const double median = c["median"].get<double>();
    if (!(median > 0) || !std::isfinite(median))
      throw ConfigError(path, "case \"" + c["id"].get<std::string>() + "\": median " + c["median"].dump() +
                                  " is not a rate > 0 (no ratio can be made to it)");
    medians[c["id"].get<std::string>()] = median;
  }
  return medians;
}

/// Rough wall seconds of a case, for the line printed before any runs: every step of the warm-up
/// and of the timed runs at a nominal rate measured here (2026-12-02, one core of this 2-core
/// machine: 2D SP ~4e7, 3D SP ~1.3e7 particle-steps/s, DP ~2.4e7 vertex-steps/s), plus a second
/// per placement and FIRE relaxation (one per run and one for the warm-up).
double estimated_seconds(const BenchCase& bc, int runs) {
  const bool dp = bc.config.is_dp();
  const double points = dp ? double(bc.config.N) * bc.config.dp.n_v : double(bc.config.N);
  const double rate = dp ? 2.4e7 : bc.config.dimension == 3 ? 1.3e7 : 4e7;
  const double warmup_steps = bc.warmup_time / choose_time_step(bc.config).dt;
  return (warmup_steps + double(runs) * double(bc.steps)) * points / rate + (runs + 1);
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_status) {
  struct Args {
    int runs = 3;
    std::vector<std::string> cases;
    double scale = 1.0;
    double skin = 0;
    std::string json_out, baseline;
    int threads = 1;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("bench", "Standard performance cases: particle-steps per second");
  cmd->add_option("--runs", a->runs, "timed runs per case (median and spread)")->check(CLI::Range(1, 100));
  cmd->add_option("--case", a->cases, "cases to run (a .. h; default all)");
  cmd->add_option("--scale", a->scale, "multiply the timed steps by this")->check(CLI::PositiveNumber);
  cmd->add_option("--skin", a->skin, "Verlet skin (default: the job default)")->check(CLI::PositiveNumber);
  cmd->add_option("--json", a->json_out, "also write the results as JSON to this file (- for stdout)");
  cmd->add_option("--baseline", a->baseline, "an earlier --json output: print each case's ratio to it");
  cmd->add_option("--threads", a->threads, "threads per run (SP and DP; the same results for every count)")
      ->capture_default_str();
  cmd->callback([a, &exit_status] {
    exit_status = guarded("bench", [&] {
    human = a->json_out == "-" ? stderr : stdout;
    check_threads("--threads", a->threads);
    const std::map<std::string, double> baseline = a->baseline.empty() ? std::map<std::string, double>{} : read_baseline(a->baseline);
    std::vector<BenchCase> chosen;
    const std::vector<BenchCase> all = standard_cases(a->scale, a->skin);
    std::string ids;
    for (const BenchCase& bc : all) ids += (ids.empty() ? "" : ", ") + bc.id;
    for (const std::string& id : a->cases)
      if (std::none_of(all.begin(), all.end(), [&](const BenchCase& bc) { return bc.id == id; }))
        throw ConfigError("--case", "\"" + id + "\": no such case (the cases: " + ids + ")");
    for (const BenchCase& bc : all)
      if (a->cases.empty() || std::find(a->cases.begin(), a->cases.end(), bc.id) != a->cases.end()) chosen.push_back(bc);
    for (std::size_t k = 0; k < all.size(); ++k)
      if (all[k].steps < 1 &&
          (a->cases.empty() || std::find(a->cases.begin(), a->cases.end(), all[k].id) != a->cases.end())) {
        char scale[32];
        std::snprintf(scale, sizeof scale, "%g", a->scale);
        const std::int64_t at_one = standard_cases(1.0, a->skin)[k].steps;
        throw ConfigError("--scale", std::string(scale) + " leaves case " + all[k].id + " no timed step (" +
                                         std::to_string(at_one) + " at scale 1: at least " + std::to_string(0.5 / at_one) + ")");
      }
    // a baseline without a chosen case: said before the runs, not found missing after them
    for (const BenchCase& bc : chosen)
      if (!baseline.empty() && !baseline.count(bc.id))
        std::fprintf(human, "bench: the baseline %s has no case %s: no ratio for it\n", terminal_safe(a->baseline).c_str(),
                     bc.id.c_str());
    double estimate = 0;
    for (const BenchCase& bc : chosen) estimate += estimated_seconds(bc, a->runs);
    std::fprintf(human, "bench: %zu case(s) x %d runs; roughly %.0f s on a machine like the one it was written on "
                "(the DP cases' warm-up of 0.3 t0 takes most of theirs)\n",
                chosen.size(), a->runs, estimate);
    std::fflush(human);
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json cases = nlohmann::json::array();
    for (const BenchCase& bc : chosen) {
      const CaseResult r = bc.config.dimension == 2 ? run_case<2>(bc, a->runs, a->threads) : run_case<3>(bc, a->runs, a->threads);
      cases.push_back(to_json(r));
      const auto it = baseline.find(r.id);
      if (it != baseline.end()) {
        std::fprintf(human, "   %s: %.3f x the baseline's median (%.3g %s)\n", r.id.c_str(), r.median / it->second, it->second,
                    r.unit.c_str());
        cases.back()["baseline_median"] = it->second;
        cases.back()["ratio_to_baseline"] = r.median / it->second;
      }
      std::fflush(human);
    }
    std::fprintf(human, "bench: done in %.0f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (!a->json_out.empty()) {
      const nlohmann::json out = {{"engine_version", BEVERLOO_VERSION}, {"runs", a->runs}, {"scale", a->scale},
                                  {"cases", cases}};
      if (a->json_out == "-")
        std::fprintf(stdout, "%s\n", out.dump(2).c_str());
      else
        write_text_atomically(a->json_out, out.dump(2) + "\n");
    }
    return exit_code::kOk;
    });
  });
}

}  // namespace beverloo
