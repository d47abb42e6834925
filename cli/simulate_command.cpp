// `beverloo simulate JOB.json [-o DIR] [--resume] [--overwrite] [--json]`: one engine run, no database.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <fstream>
#include <iostream>

#include "core/atomic_file.h"
#include "commands.h"
#include "core/cpus.h"
#include "engine/models/model_time_step.h"
#include "engine/protocol/memory_estimate.h"
#include "engine/io/job_output.h"
#include "engine/json_file.h"
#include "engine/protocol/run_hopper.h"
#include "core/failures.h"
#include "core/stop_signal.h"
#include "core/text_escape.h"
#include "core/user_file.h"

namespace beverloo {
namespace fs = std::filesystem;
namespace {

struct SimulateArgs {
  std::string job_path;
  std::string out_dir;
  bool resume = false;
  std::string continue_from;
  bool overwrite = false;
  bool json = false;
  double checkpoint_wall_seconds = 600;
  std::string progress = "auto";
  int threads = 1;
};

/// The job file's errors name the file (read_json_file's own already do), then the field.
SimConfig read_job(const std::string& path) {
  const nlohmann::json j = read_json_file(path);
  try {
    SimConfig c = SimConfig::from_json(j);
    (void)choose_time_step(c);  // refuse an unstable explicit dt before anything is written
    check_memory(c);            // and a job this machine cannot hold
    return c;
  } catch (const ConfigError& e) {
    throw ConfigError(path, e.what());
  }
}

void print_summary(const RunResult& r, const SimConfig& c) {
  std::printf("status        %s (%s)\n", terminal_safe(r.status).c_str(), terminal_safe(r.stop_reason).c_str());
  if (r.draining) {
    std::printf("Q = c0 t0     %.6g +- %.3g (%.2f%%)  [dN/dt = -c0 sqrt(N); c0 per t0]\n", r.Q, r.Q_err, 100 * r.Q_rel_err);
    std::printf("drain         %d -> %d particles; fit over %d exits in %d blocks (%.1f .. %.1f t0), chi2_red %.2f%s%s\n",
                r.n_initial, r.n_remaining, r.drain.exits_used, r.drain.blocks, r.window_start, r.window_end,
                r.drain.chi2_red, r.drain.ok ? "" : "; no fit: ", r.drain.message.c_str());
  } else {
    std::printf("Q             %.6g +- %.3g (%.2f%%)  [sigma_avg^%d / t0]\n", r.Q, r.Q_err, 100 * r.Q_rel_err, c.dimension);
    std::printf("window        %.1f .. %.1f t0, %lld exits in window, %lld in all\n", r.window_start, r.window_end,
                static_cast<long long>(r.exits_in_window), static_cast<long long>(r.exits_total));
  }
  if (r.clogged) std::printf("clog          last exit at t = %.1f, detected at t = %.1f\n", r.clog_time, r.clog_detected_time);
  std::printf("rho_n         %.4g +- %.2g   Q' = %.6g\n", r.rho_n, r.rho_n_err, r.Q_prime);
  std::printf("|F_drag|      %.4g   |F_friction| %.4g   ratio %.4g", r.mean_F_drag, r.mean_F_friction, r.force_ratio);
  if (std::isfinite(r.force_ratio_err)) std::printf(" +- %.2g", r.force_ratio_err);  // none without friction
  std::printf("\n");
  std::printf("dt            %.4g (limited by %s), %lld steps, seed %llu\n", r.dt, terminal_safe(r.dt_limiting_term).c_str(),
              static_cast<long long>(r.steps), static_cast<unsigned long long>(r.seed));
  std::printf("speed         %.3g particle-steps/s, %.1f s wall\n", r.particle_steps_per_second, r.wall_seconds);
}

int run_simulate(const SimulateArgs& a) {
  SimConfig c;
  try {
    c = read_job(a.job_path);
    check_threads("--threads", a.threads);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "beverloo simulate: configuration error: %s\n", terminal_safe(e.what()).c_str());
    return exit_code::kConfig;
  }
  const std::string dir = a.out_dir.empty() ? (fs::path("out") / fs::path(a.job_path).stem()).string() : a.out_dir;
  const fs::path result = fs::path(dir) / job_output::kResult, checkpoint = fs::path(dir) / job_output::kCheckpoint;
  try {
    if (!a.resume && (fs::exists(result) || fs::exists(checkpoint))) {
      if (!a.overwrite) {
        std::fprintf(stderr,
                     "beverloo simulate: %s already holds a run; use --resume to continue it or --overwrite to start over\n",
                     terminal_safe(dir).c_str());
        return exit_code::kConfig;
      }
      for (const char* name : {job_output::kResult, job_output::kCheckpoint, job_output::kSummary, job_output::kFailure,
                               job_output::kTrajectory})
        fs::remove(fs::path(dir) / name);
    }
    if (a.resume) {
      // a directory of another job (its job.json, written when that run began, differs) is the
      // wrong directory: refused, also when it holds only that job's checkpoint
      const fs::path job_file = fs::path(dir) / "job.json";
      if (fs::exists(checkpoint) && fs::exists(job_file)) {
        nlohmann::json theirs;
        try {
          theirs = nlohmann::json::parse(read_user_file(job_file.string(), 1 << 20));
        } catch (const std::exception&) {
          theirs = nullptr;  // unreadable: the checkpoint's own check decides (set aside if it is not this job's)
        }
        if (!theirs.is_null() && theirs != c.to_json()) {
          std::fprintf(stderr, "beverloo simulate: %s holds another job's run (its job.json differs); use another -o, or "
                               "--overwrite without --resume to start this job there\n", terminal_safe(dir).c_str());
          return exit_code::kConfig;
        }
      }
      const job_output::ResultCheck done = job_output::check_result(dir, c);
      if (done.state == job_output::ResultState::OtherJob) {
        std::fprintf(stderr, "beverloo simulate: %s\n", terminal_safe(done.reason).c_str());
        return exit_code::kConfig;
      }
      if (done.state == job_output::ResultState::Complete) {
        std::fprintf(stderr, "beverloo simulate: %s is already complete\n", terminal_safe(dir).c_str());
        return exit_code::kOk;
      }
      if (done.state == job_output::ResultState::Damaged) {
        std::fprintf(stderr, "beverloo simulate: %s; running the job again\n", terminal_safe(done.reason).c_str());
        job_output::remove_result(dir);
      }
    }
    fs::create_directories(dir);
    write_text_atomically((fs::path(dir) / "job.json").string(), c.to_json().dump(2) + "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beverloo simulate: I/O error: %s\n", terminal_safe(e.what()).c_str());
    return exit_code::kIo;
  }

  RunOptions opt;
  opt.output_dir = dir;
  opt.resume = a.resume;
  opt.continue_from = a.continue_from;
  opt.progress = a.progress == "terminal" ? ProgressMode::Terminal
                 : a.progress == "log"    ? ProgressMode::Log
                 : a.progress == "quiet"  ? ProgressMode::Quiet
                                          : ProgressMode::Auto;
  opt.checkpoint_wall_seconds = a.checkpoint_wall_seconds;
  opt.threads = a.threads;
  opt.stop_request = install_stop_handlers();
  // failure.json for people; the class and the exit code come from the one table
  auto fail = [&](FailureClass cls, const char* what, const std::string& message) {
    std::fprintf(stderr, "\nbeverloo simulate: %s: %s\n", what, terminal_safe(message).c_str());
    try {
      nlohmann::json j = {{"status", "failed"}, {"failure_class", std::string(to_string(cls))}, {"message", message}};
      write_text_atomically((fs::path(dir) / "failure.json").string(), j.dump(2) + "\n");
    } catch (...) {
    }
    return failure_info(cls).exit_code;
  };
  try {
    const RunResult r = run_hopper(c, opt);
    if (r.status == "interrupted") {
      std::fprintf(stderr, "beverloo simulate: %s\n", terminal_safe(r.stop_reason).c_str());
      return exit_code::kInterrupted;
    }
    if (a.json)
      std::cout << r.summary_json().dump(2) << "\n";
    else
      print_summary(r, c);
    return exit_code::kOk;
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "beverloo simulate: configuration error: %s\n", terminal_safe(e.what()).c_str());
    return failure_info(FailureClass::InvalidParameters).exit_code;
  } catch (const InstabilityError& e) {
    return fail(FailureClass::BlowUp, "unstable run", terminal_safe(e.what()).c_str());
  } catch (const IoError& e) {
    return fail(FailureClass::Io, "I/O error", terminal_safe(e.what()).c_str());
  } catch (const std::bad_alloc&) {
    return fail(FailureClass::OutOfMemory, "out of memory",
                "an allocation failed (the machine's memory, or this process's limit: ulimit -v, a cgroup's memory.max, "
                "Slurm's --mem)");
  }
}

}  // namespace

void add_simulate_command(CLI::App& app, int& exit_status) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "Run one hopper flow from a job file (no database)");
  cmd->add_option("JOB", args->job_path, "job file (JSON)")->required();
  cmd->add_option("-o,--output", args->out_dir, "output directory (default: out/<job name>)");
  cmd->add_flag("--resume", args->resume, "continue from DIR/checkpoint.h5 if present");
  cmd->add_option("--continue-from", args->continue_from,
                  "another job's checkpoint.h5 to continue when DIR holds no checkpoint: a job that differs from this "
                  "one only in run.t_max, run.target_rel_err, run.stop_unreachable or run.min_time and stopped earlier "
                  "(the result is that of a run from the start, bit for bit; otherwise the run starts from the beginning)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--overwrite", args->overwrite, "discard a run already in DIR");
  cmd->add_flag("--json", args->json, "print the result summary as JSON");
  cmd->add_option("--checkpoint-wall", args->checkpoint_wall_seconds,
                  "also checkpoint after this many wall seconds since the last checkpoint (0: only every "
                  "run.checkpoint_interval of simulated time); results do not depend on it")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--threads", args->threads,
                  "threads for this job's steps (SP and DP); every count gives the same result, bit for bit")
      ->capture_default_str();
  cmd->add_option("--progress", args->progress, "auto | terminal | log | quiet")
      ->check(CLI::IsMember({"auto", "terminal", "log", "quiet"}));
  cmd->callback([args, &exit_status] { exit_status = run_simulate(*args); });
}

}  // namespace beverloo
