// Campaign commands: run, sweep check/expand, campaign create/run/status/retry/cancel, worker.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <tuple>

#include "commands.h"
#include "guarded.h"
#include "core/errors.h"
#include "core/failures.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "orchestrator/campaign/coordinator.h"
#include "orchestrator/executors/executor_factory.h"
#include "engine/protocol/run_result.h"
#include "orchestrator/campaign/store.h"
#include "orchestrator/campaign/job_explain.h"
#include "orchestrator/campaign/job_speed.h"
#include "reports/adaptive_planner.h"
#include "orchestrator/sweep/adaptive_spec.h"
#include "orchestrator/campaign/worker.h"
#include "orchestrator/db/migrations.h"
#include "core/text_escape.h"
#include "engine/json_file.h"
#include "engine/parameters.h"
#include "orchestrator/sweep/sweep.h"
#include "core/version.h"

namespace beverloo {
namespace fs = std::filesystem;
namespace {

Sweep load_sweep(const std::string& path, std::vector<JobSpec>* jobs, std::string* text = nullptr) {
  Sweep s = Sweep::load(path, text);
  if (jobs) *jobs = s.expand();
  return s;
}

std::string fmt(const nlohmann::json& v) {
  if (v.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
    return buf;
  }
  return v.is_string() ? v.get<std::string>() : v.dump();
}

int expand_command(const std::string& path, const std::string& format) {
  std::vector<JobSpec> jobs;
  const Sweep s = load_sweep(path, &jobs);
  // columns: every parameter any point sets, then the resolved dissipation
  std::vector<std::string> cols;
  for (const JobSpec& j : jobs)
    for (auto it = j.point.begin(); it != j.point.end(); ++it)
      if (std::find(cols.begin(), cols.end(), it.key()) == cols.end()) cols.push_back(it.key());
  for (const char* extra : {"zeta", "mu"})
    if (std::find(cols.begin(), cols.end(), extra) == cols.end()) cols.push_back(extra);
  auto value = [](const JobSpec& j, const std::string& c) -> nlohmann::json {
    if (j.point.contains(c)) return j.point[c];
    if (j.job.contains(c)) return j.job[c];
    return nullptr;
  };
  if (format == "json") {
    nlohmann::json out = nlohmann::json::array();
    for (const JobSpec& j : jobs) out.push_back({{"key", j.key}, {"point", j.point}, {"job", j.job}});
    std::cout << out.dump(2) << "\n";
    return exit_code::kOk;
  }
  const char* sep = format == "csv" ? "," : "  ";
  std::printf(format == "csv" ? "%s" : "%-16s", "key");
  // csv: RFC 4180 fields (the data as it is); table: what a terminal shows as written
  auto cell = [&](const std::string& text) { return format == "csv" ? csv_field(text) : terminal_safe(text); };
  for (const auto& c : cols) std::printf(format == "csv" ? "%s%s" : "%s%-12s", sep, cell(c).c_str());
  std::printf("\n");
  for (const JobSpec& j : jobs) {
    std::printf(format == "csv" ? "%s" : "%-16s", (format == "csv" ? j.key : j.key.substr(0, 16)).c_str());
    for (const auto& c : cols) std::printf(format == "csv" ? "%s%s" : "%s%-12s", sep, cell(fmt(value(j, c))).c_str());
    std::printf("\n");
  }
  if (format == "table") std::printf("(%zu jobs from sweep \"%s\")\n", jobs.size(), terminal_safe(s.name).c_str());
  return exit_code::kOk;
}

/// An adaptive campaign's decisions (reports/adaptive_planner.h): per series, the jobs added and
/// the last decision with its reason.
void print_adaptive_decisions(db::Database& db, std::int64_t campaign) {
  db::Statement has = db.prepare("SELECT count(*) FROM sqlite_master WHERE name = 'adaptive_decisions'");
  if (!has.step() || has.get_int(0) == 0) return;  // a database of an older schema (read as it is)
  db::Statement st = db.prepare(
      "SELECT series_key, sum(action = 'add'), (SELECT d2.action || ': ' || d2.reason FROM adaptive_decisions d2 "
      "WHERE d2.campaign_id = d.campaign_id AND d2.series_key = d.series_key ORDER BY d2.seq DESC LIMIT 1) "
      "FROM adaptive_decisions d WHERE campaign_id = ?1 GROUP BY series_key ORDER BY min(rowid)");
  st.bind(1, campaign);
  bool first = true;
  while (st.step()) {
    std::printf("%s series %s: %lld added; last: %s\n", first ? "adaptive    " : "            ",
                terminal_safe(st.get_text(0).substr(0, 12)).c_str(), (long long)st.get_int(1),
                terminal_safe(st.get_text(2)).c_str());
    first = false;
  }
}

int status_command(const std::string& dir) {
  CampaignReader reader(dir);
  db::Database& db = reader.db();
  CampaignStore store(db);
  const std::int64_t id = store.latest_campaign();
  if (id < 0) throw SweepError(dir, "holds no campaign");
  db::Statement name = db.prepare("SELECT name, created_at FROM campaigns WHERE id = ?1");
  name.bind(1, id);
  name.step();
  const StateCounts c = store.counts(id);
  std::printf("campaign     %s (created %s) in %s\n", terminal_safe(name.get_text(0)).c_str(), terminal_safe(name.get_text(1)).c_str(), terminal_safe(dir).c_str());
  std::printf("jobs         %lld: %lld done, %lld clogged, %lld failed, %lld cancelled, %lld running, %lld pending\n",
              (long long)c.total(), (long long)c.done, (long long)c.clogged, (long long)c.failed, (long long)c.cancelled,
              (long long)c.running, (long long)c.pending);
  // what each state and each run ending present here means, once
  const std::pair<const char*, std::int64_t> states[] = {{"done", c.done}, {"clogged", c.clogged}, {"failed", c.failed},
                                                          {"cancelled", c.cancelled}, {"running", c.running}, {"pending", c.pending}};
  for (const auto& [state, count] : states)
    if (count > 0) std::printf("  %-10s %s\n", state, job_state_meaning(state));
  // a campaign begun with another engine: how many jobs each version holds, and in which states
  db::Statement engines = db.prepare(
      "SELECT j.engine_version, count(*), sum(j.state IN ('done', 'clogged')), sum(j.state = 'cancelled') FROM jobs j "
      "JOIN campaign_jobs cj ON cj.job_key = j.key WHERE cj.campaign_id = ?1 GROUP BY 1 ORDER BY 1 DESC");
  engines.bind(1, id);
  std::vector<std::string> versions;
  bool another = false;
  while (engines.step()) {
    another = another || engines.get_text(0) != BEVERLOO_VERSION;
    versions.push_back(terminal_safe(engines.get_text(0)) + ": " + std::to_string(engines.get_int(1)) + " jobs (" +
                       std::to_string(engines.get_int(2)) + " with a result, " + std::to_string(engines.get_int(3)) +
                       " cancelled)");
  }
  if (another) {
    std::printf("engines      this is %s; jobs by the engine that expanded them:", BEVERLOO_VERSION);
    for (const std::string& v : versions) std::printf(" %s;", v.c_str());
    std::printf(" a job runs only on its own engine\n");
  }
  print_adaptive_decisions(db, id);
  db::Statement endings = db.prepare(
      "SELECT r.status, count(*) FROM results r JOIN campaign_jobs cj ON cj.job_key = r.job_key "
      "WHERE cj.campaign_id = ?1 GROUP BY 1 ORDER BY 1");
  endings.bind(1, id);
  bool first = true;
  while (endings.step()) {
    const std::string status = endings.get_text(0);
    std::printf("%s %lld %s: %s\n", first ? "runs ended  " : "            ", (long long)endings.get_int(1), terminal_safe(status).c_str(),
                run_status_meaning(status));
    first = false;
  }
  db::Statement tp = db.prepare(
      "SELECT count(*), (julianday(max(a.ended_at)) - julianday(min(a.started_at))) * 86400, sum(r.wall_seconds) "
      "FROM attempts a JOIN results r ON r.attempt_id = a.id JOIN campaign_jobs cj ON cj.job_key = a.job_key "
      "WHERE cj.campaign_id = ?1");
  tp.bind(1, id);
  tp.step();
  const double n = tp.get_int(0), span = tp.get_double(1), compute = tp.get_double(2);
  if (n > 0 && span > 0) {
    const double per_hour = n / span * 3600;
    std::printf("throughput   %.1f jobs/hour over %.0f s; %.0f s of engine time\n", per_hour, span, compute);
    if (c.pending + c.running > 0) std::printf("ETA          %.0f s at that rate\n", (c.pending + c.running) / per_hour * 3600);
  }
  db::Statement fails = db.prepare(
      "SELECT a.failure_class, count(*) FROM attempts a JOIN campaign_jobs cj ON cj.job_key = a.job_key "
      "WHERE cj.campaign_id = ?1 AND a.failure_class IS NOT NULL GROUP BY a.failure_class ORDER BY 2 DESC");
  fails.bind(1, id);
  std::string classes;
  while (fails.step()) classes += (classes.empty() ? "" : ", ") + fails.get_text(0) + " " + std::to_string(fails.get_int(1));
  std::printf("failures     %s\n", classes.empty() ? "none" : terminal_safe(classes).c_str());
  // the unit to plan the rest of a campaign with (docs/cli.md)
  bool first_speed = true;
  for (const ModelSpeed& m : campaign_speed(db, CampaignScope::one(id))) {
    std::printf("%s %s: %.3g t0 per CPU-minute per job (median of %d; %.3g-%.3g)\n", first_speed ? "speed       " : "            ",
                m.model.c_str(), m.median, m.jobs, m.min, m.max);
    first_speed = false;
  }
  if (db.scalar_int("PRAGMA user_version") >= 4 && db.scalar_int("SELECT count(*) FROM slurm_submissions") > 0) {
    // Slurm's view as the coordinator last saw it (attempts.slurm_state), per state
    db::Statement arrays = db.prepare("SELECT count(*), coalesce(sum(array_size), 0) FROM slurm_submissions WHERE state = 'submitted'");
    arrays.step();
    db::Statement live = db.prepare(
        "SELECT coalesce(a.slurm_state, 'not submitted'), count(*) FROM attempts a JOIN campaign_jobs cj ON cj.job_key = a.job_key "
        "WHERE cj.campaign_id = ?1 AND a.state = 'running' AND a.executor = 'slurm' GROUP BY 1 ORDER BY 2 DESC");
    live.bind(1, id);
    std::string states;
    while (live.step()) states += (states.empty() ? "" : ", ") + live.get_text(0) + " " + std::to_string(live.get_int(1));
    std::printf("slurm        %lld arrays, %lld tasks; attempts in flight: %s\n", (long long)arrays.get_int(0),
                (long long)arrays.get_int(1), states.empty() ? "none" : terminal_safe(states).c_str());
  }
  return exit_code::kOk;
}


/// `campaign explain`: is this job cached here, and if not, which stored job is nearest and how
/// does it differ (docs/cli.md).
int explain_command(const std::string& dir, const std::string& what) {
  CampaignReader reader(dir);  // read-only: also while a coordinator runs
  db::Database& db = reader.db();
  std::string key, source;
  nlohmann::json job;
  std::vector<std::string> identity_free;
  if (fs::is_regular_file(what)) {
    SimConfig c;
    try {
      c = SimConfig::from_json(read_json_file(what));
    } catch (const ConfigError& e) {
      throw SweepError(what, e.what());
    }
    key = job_key(c);
    job = c.to_json();
    identity_free = identity_free_paths(c);
    source = what;
  } else {
    try {
      std::tie(key, job) = find_stored_job(db, what);
    } catch (const std::invalid_argument& e) {
      throw SweepError(what, std::string(e.what()) + " (no such file either)");
    }
    try {
      identity_free = identity_free_paths(SimConfig::from_json(job));
    } catch (const ConfigError&) {
      // a job of another engine's parameter set: every field counts
    }
    source = "stored job";
  }
  const JobExplanation x = explain_job(db, key, job, identity_free);
  std::printf("job          %s (%s), engine %s\n", key.c_str(), terminal_safe(source).c_str(), BEVERLOO_VERSION);
  auto describe = [](const StoredJob& s) {
    std::string d = s.state;
    if (!s.result_status.empty()) {
      char q[96];
      std::snprintf(q, sizeof q, ", Q = %.4g +- %.2g (%s)", s.Q, s.Q_err, s.result_status.c_str());
      d += q;
    }
    return d + ", engine " + s.engine_version;
  };
  if (x.found && (x.found->state == "done" || x.found->state == "clogged")) {
    std::printf("cached       yes: %s; `beverloo run` reuses it\n", terminal_safe(describe(*x.found)).c_str());
    return exit_code::kOk;
  }
  if (x.found)
    std::printf("cached       no: in the store, %s (`beverloo campaign run` runs it)\n", terminal_safe(describe(*x.found)).c_str());
  else
    std::printf("cached       no: not in this store (a run of a sweep holding it computes it)\n");
  if (!x.nearest) {
    std::printf("nearest      none: no finished job among %lld stored\n", x.stored_jobs);
    return exit_code::kOk;
  }
  std::printf("nearest      %s: %s\n", x.nearest->key.c_str(), terminal_safe(describe(*x.nearest)).c_str());
  if (x.only_engine_differs) {
    std::printf("differs in   nothing but the engine version (%s stored, %s here): results of another engine "
                "version are not reused, because its bits may differ\n",
                terminal_safe(x.nearest->engine_version).c_str(), BEVERLOO_VERSION);
    return exit_code::kOk;
  }
  std::printf("differs in   %zu field%s (of the job's identity; checkpoint cadence, skin and other settings that cannot "
              "change a result do not count):\n", x.differences.size(), x.differences.size() == 1 ? "" : "s");
  for (const FieldDifference& d : x.differences)
    std::printf("  %-24s this %-16s stored %s\n", terminal_safe(d.field).c_str(), terminal_safe(d.asked).c_str(),
                terminal_safe(d.stored).c_str());
  if (x.nearest->engine_version != BEVERLOO_VERSION)
    std::printf("  %-24s this %-16s stored %s\n", "(engine version)", BEVERLOO_VERSION,
                terminal_safe(x.nearest->engine_version).c_str());
  // only when it stops differs: the same trajectory, whose run need not start over
  bool only_stopping_rules = x.nearest->engine_version == BEVERLOO_VERSION && !x.differences.empty();
  for (const FieldDifference& d : x.differences) {
    const ParamSpec* row = find_parameter(d.field);
    only_stopping_rules = only_stopping_rules && row && row->stop_rule;
  }
  if (only_stopping_rules)
    std::printf("continues    only its stopping rules differ (the same trajectory): if it stops later, it continues "
                "the stored job's final checkpoint instead of starting over (docs/job-file.md, run.min_time)\n");
  return exit_code::kOk;
}

template <class F>
int with_store(const std::string& dir, F&& body) {
  CampaignWriter writer(dir, CampaignWriter::Open::MustExist);  // one writer at a time
  CampaignStore store(writer.db());
  const std::int64_t id = store.latest_campaign();
  if (id < 0) throw SweepError(dir, "holds no campaign");
  return body(store, id);
}

}  // namespace

void add_campaign_commands(CLI::App& app, int& exit_status) {
  auto opts = std::make_shared<CampaignOptions>();
  auto sweep_path = std::make_shared<std::string>();
  auto progress = std::make_shared<std::string>("auto");
  auto to_mode = [](const std::string& p) {
    return p == "terminal" ? ProgressMode::Terminal : p == "log" ? ProgressMode::Log : p == "quiet" ? ProgressMode::Quiet : ProgressMode::Auto;
  };
  // where workers run (docs/cluster.md)
  auto add_executor_options = [opts](CLI::App* cmd) {
    cmd->add_option("--executor", opts->executor, "local (worker processes here) | slurm (job arrays)")
        ->check(CLI::IsMember(executor_names()));
    // each executor's own options, as it declares them (orchestrator/executors): checked here
    // by kind and range, parsed by the executor
    for (const DeclaredOption& d : declared_executor_options()) {
      const ExecutorOption o = d.option;
      auto check = CLI::Validator(
          [o](std::string& text) -> std::string {
            if (o.kind != ExecutorOption::Kind::Integer && o.kind != ExecutorOption::Kind::Real) return "";
            try {
              option_number(o, text);
            } catch (const ConfigError& e) {
              const std::string what = e.what();  // "FLAG: reason": CLI11 names the flag itself
              return what.substr(std::min(what.size(), o.flag.size() + 2));
            }
            return "";
          },
          "");
      if (o.kind == ExecutorOption::Kind::TextList)
        cmd->add_option_function<std::vector<std::string>>(
               o.flag, [opts, o](const std::vector<std::string>& v) { opts->executor_options[o.flag] = v; }, o.help)
            ->allow_extra_args(false)
            ->check(check);
      else
        cmd->add_option_function<std::string>(
               o.flag, [opts, o](const std::string& v) { opts->executor_options[o.flag] = {v}; }, o.help)
            ->check(check)
            ->type_name(o.kind == ExecutorOption::Kind::Integer ? "INT" : o.kind == ExecutorOption::Kind::Real ? "FLOAT" : "TEXT");
    }
  };
  auto add_run_options = [&](CLI::App* cmd) {
    cmd->add_option("--dir", opts->dir, "campaign directory (default: campaigns/<sweep name>)");
    cmd->add_option("--workers", opts->workers, "worker processes (default: the number of cores over --threads)")
        ->check(CLI::Range(1, 4096));
    cmd->add_option("--threads", opts->threads,
                    "threads per job (SP and DP; the same results for every count): locally workers x threads must fit the "
                    "cores, on Slurm each task asks --cpus-per-task=THREADS (default 1)")
        ->check(CLI::Range(1, 4096));
    cmd->add_option("--max-retries", opts->max_retries, "retries per job for blow-ups and I/O errors")->check(CLI::Range(0, 100));
    cmd->add_option("--job-timeout", opts->job_timeout_s, "wall seconds per attempt; then checkpoint and resume later");
    cmd->add_option("--heartbeat", opts->heartbeat_s, "seconds between heartbeat records of live workers (default 30)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--progress", *progress, "auto | terminal | log | quiet")->check(CLI::IsMember({"auto", "terminal", "log", "quiet"}));
    add_executor_options(cmd);
  };

  CLI::App* run = app.add_subcommand("run", "Create or reopen a campaign and run every job that is not done");
  run->add_option("SWEEP", *sweep_path, "sweep file (JSON)")->required();
  add_run_options(run);
  run->callback([=, &exit_status] {
    exit_status = guarded("run", [&] {
      CampaignOptions o = *opts;
      if (o.dir.empty() || o.dir == "campaign") o.dir = (fs::path("campaigns") / fs::path(*sweep_path).stem()).string();
      o.progress = to_mode(*progress);
      AdaptivePlanner planner;  // grows a campaign whose sweep has an "adaptive" block; else adds nothing
      o.planner = &planner;
      const int rc = run_campaign(*sweep_path, o);
      if (rc != exit_code::kOk && rc != exit_code::kJobsFailed) return rc;
      const int report = report_campaign(o.dir, campaign_dir::report_path(o.dir));
      return rc != exit_code::kOk ? rc : report;
    });
  });

  CLI::App* sweep = app.add_subcommand("sweep", "Check or expand a sweep file without running it");
  sweep->require_subcommand(1);
  CLI::App* check = sweep->add_subcommand("check", "Validate a sweep file");
  auto check_path = std::make_shared<std::string>();
  check->add_option("FILE", *check_path)->required();
  check->callback([=, &exit_status] {
    exit_status = guarded("sweep check", [&] {
      std::vector<JobSpec> jobs;
      const Sweep s = load_sweep(*check_path, &jobs);
      std::printf("%s: valid, sweep \"%s\", %zu jobs\n", terminal_safe(*check_path).c_str(), terminal_safe(s.name).c_str(), jobs.size());
      if (const std::optional<AdaptiveSpec> a = AdaptiveSpec::of_sweep(s.source)) {
        // the grid is the start: say what the planner will add to (docs/sweeps.md)
        std::printf("adaptive: the grid is the start; per series up to %d more jobs at w in [%g, %g] every %g, until", a->max_added_jobs,
                    a->w_lo, a->w_hi, a->w_step);
        if (a->k_err) std::printf(" k_err <= %g", *a->k_err);
        if (a->k_err && a->beta_err) std::printf(" and");
        if (a->beta_err) std::printf(" beta_err <= %g", *a->beta_err);
        std::printf("\n");
        if (const auto& l = a->lambda) {
          std::printf("adaptive lambda: per beta(lambda) group up to %d more series at lambda in [%g, %g], %d per decade, until",
                      l->max_added_series, l->lambda_lo, l->lambda_hi, l->per_decade);
          // the targets given, joined by "and": the crossing's first, as the planner pursues it
          const char* joint = "";
          if (l->crossing_interpolation_err)
            std::printf(" crossing_interpolation_err <= %g", *l->crossing_interpolation_err), joint = " and";
          if (l->log10_lambda_c_err) std::printf("%s log10_lambda_c_err <= %g", joint, *l->log10_lambda_c_err), joint = " and";
          if (l->b_err) std::printf("%s b_err <= %g", joint, *l->b_err);
          std::printf("\n");
        }
      }
      return exit_code::kOk;
    });
  });
  CLI::App* expand = sweep->add_subcommand("expand", "List the jobs of a sweep with their keys");
  auto expand_path = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("table");
  expand->add_option("FILE", *expand_path)->required();
  expand->add_option("--format", *format, "table | csv | json")->check(CLI::IsMember({"table", "csv", "json"}));
  expand->callback([=, &exit_status] { exit_status = guarded("sweep expand", [&] { return expand_command(*expand_path, *format); }); });

  CLI::App* campaign = app.add_subcommand("campaign", "The pieces of `run`, one at a time");
  campaign->require_subcommand(1);
  auto dir = std::make_shared<std::string>("campaign");
  CLI::App* create = campaign->add_subcommand("create", "Create the campaign of a sweep without running it");
  auto create_path = std::make_shared<std::string>();
  create->add_option("SWEEP", *create_path)->required();
  create->add_option("--dir", *dir, "campaign directory");
  create->callback([=, &exit_status] {
    exit_status = guarded("campaign create", [&] {
      std::vector<JobSpec> jobs;
      std::string text;
      const Sweep s = load_sweep(*create_path, &jobs, &text);
      CampaignWriter writer(*dir, CampaignWriter::Open::CreateIfMissing);
      CampaignStore(writer.db()).create_campaign(s, text, jobs);
      std::printf("campaign \"%s\" with %zu jobs in %s\n", terminal_safe(s.name).c_str(), jobs.size(), terminal_safe(*dir).c_str());
      return exit_code::kOk;
    });
  });
  CLI::App* crun = campaign->add_subcommand("run", "Run the jobs of an existing campaign that are not done");
  crun->add_option("--dir", opts->dir, "campaign directory");
  crun->add_option("--workers", opts->workers, "worker processes");
  crun->add_option("--threads", opts->threads, "threads per job (as for run)")->check(CLI::Range(1, 4096));
  crun->add_option("--progress", *progress, "auto | terminal | log | quiet");
  crun->add_option("--heartbeat", opts->heartbeat_s, "seconds between heartbeats of live workers (default 30)")->check(CLI::PositiveNumber);
  add_executor_options(crun);
  crun->callback([=, &exit_status] {
    exit_status = guarded("campaign run", [&] {
      CampaignOptions o = *opts;
      o.progress = to_mode(*progress);
      AdaptivePlanner planner;
      o.planner = &planner;
      return run_campaign(std::nullopt, o);
    });
  });
  CLI::App* status = campaign->add_subcommand("status", "Counts by state, throughput, ETA, failures by class");
  status->add_option("--dir", *dir, "campaign directory");
  status->callback([=, &exit_status] { exit_status = guarded("campaign status", [&] { return status_command(*dir); }); });
  CLI::App* retry = campaign->add_subcommand("retry", "Failed jobs back to pending (retry budget reset)");
  auto include_cancelled = std::make_shared<bool>(false);
  retry->add_option("--dir", *dir, "campaign directory");
  retry->add_flag("--include-cancelled", *include_cancelled, "also cancelled jobs");
  retry->callback([=, &exit_status] {
    exit_status = guarded("campaign retry", [&] {
      return with_store(*dir, [&](CampaignStore& s, std::int64_t id) {
        std::printf("%lld jobs back to pending\n", (long long)s.retry(id, *include_cancelled));
        return exit_code::kOk;
      });
    });
  });
  CLI::App* explain = campaign->add_subcommand(
      "explain", "Is this job cached here? If not, the nearest finished job and the fields in which it differs");
  auto explain_what = std::make_shared<std::string>();
  explain->add_option("JOB", *explain_what, "a job file (JSON) or a stored job's key (at least 8 hex digits)")->required();
  explain->add_option("--dir", *dir, "campaign directory")->required();
  explain->callback([=, &exit_status] {
    exit_status = guarded("campaign explain", [&] { return explain_command(*dir, *explain_what); });
  });
  CLI::App* cancel = campaign->add_subcommand("cancel", "Pending jobs to cancelled");
  cancel->add_option("--dir", *dir, "campaign directory");
  cancel->callback([=, &exit_status] {
    exit_status = guarded("campaign cancel", [&] {
      return with_store(*dir, [&](CampaignStore& s, std::int64_t id) {
        std::printf("%lld pending jobs cancelled\n", (long long)s.cancel(id));
        return exit_code::kOk;
      });
    });
  });

  CLI::App* worker = app.add_subcommand("worker", "Run one job attempt from its spec (started by executors)");
  worker->group("");  // not for people: hidden from --help
  auto spec = std::make_shared<std::string>();
  auto manifest = std::make_shared<std::string>();
  auto task = std::make_shared<int>(-1);
  worker->add_option("SPEC", *spec, "spec.json of one attempt (local executor)");
  worker->add_option("--manifest", *manifest, "manifest.json of a Slurm submission");
  worker->add_option("--task", *task, "array index in the manifest (SLURM_ARRAY_TASK_ID)");
  worker->callback([=, &exit_status] {
    if (!manifest->empty())
      exit_status = run_worker_task(*manifest, *task);
    else if (!spec->empty())
      exit_status = run_worker(*spec);
    else
      throw CLI::ValidationError("worker", "give SPEC or --manifest M --task I");
  });
}

}  // namespace beverloo
