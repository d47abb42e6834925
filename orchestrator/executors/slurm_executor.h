#pragma once
/// \file slurm_executor.h
/// \brief The Slurm executor: claimed attempts go out as job arrays (bundled, chunked under
/// MaxArraySize, throttled), each submission recorded before sbatch runs and completed with
/// Slurm's id after; attempts are then watched from Slurm's view (squeue; sacct or the
/// jobcomp file once squeue has forgotten them) together with their heartbeat and outcome
/// files. Workers on the compute nodes never see the database. docs/cluster.md tells the story.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "executor.h"
#include "executor_options.h"
#include "orchestrator/slurm/slurm_commands.h"
#include "orchestrator/slurm/slurm_options.h"
#include "orchestrator/slurm/slurm_output.h"

namespace beverloo {

class SlurmExecutor final : public Executor {
 public:
  /// campaign_dir must be absolute: compute nodes see the job directories by that path.
  SlurmExecutor(CampaignStore& store, std::string campaign_dir, SlurmOptions options);
  /// Its command-line options (slurm_executor_options.cpp), and the settings they give, with
  /// threads per job as --cpus-per-task. Throws ConfigError for a bad value.
  static std::vector<ExecutorOption> options();
  static SlurmOptions settings_from(const ExecutorOptionValues& given, int threads);
  ~SlurmExecutor() override;
  std::string name() const override { return "slurm"; }
  std::string on_stop() const override {
    return "Slurm tasks keep running; run the same command again to collect them";
  }
  int free_slots() const override { return options_.max_in_flight - static_cast<int>(tracked_.size()); }
  int in_flight() const override { return static_cast<int>(tracked_.size()); }
  void start(const std::vector<ClaimedJob>& jobs) override;
  bool adopt(const RunningAttempt& a) override;
  std::vector<WorkerExit> poll() override;
  void wait() override;
  std::vector<WorkerExit> stop_all() override;
  void stop(std::int64_t) override {}  // Slurm enforces --time and signals the worker before it

  /// Estimated wall seconds of one job (an upper bound: the run may converge before t_max).
  static double estimated_seconds(const std::string& job_json);
  /// Groups jobs (by index) into array tasks: a fixed number per task, or (bundle = 0) greedily
  /// up to target_s of estimated work per task.
  static std::vector<std::vector<std::size_t>> bundle_jobs(const std::vector<double>& estimated_s, int bundle, double target_s);

 private:
  struct Tracked {
    std::int64_t attempt_id = 0;
    std::string dir, token;       ///< absolute job directory; the attempt's token
    std::int64_t submission = -1;
    std::string array_id;         ///< Slurm's array id
    int task = -1;
    std::string state;            ///< last state seen ("" before the first poll)
    double ended_since = -1;      ///< steady seconds: when the task was first seen ended / missing
    double running_since = -1;    ///< unix seconds: when it was first seen RUNNING
    double last_heartbeat = 0;    ///< unix seconds, from heartbeat.json (this attempt's token only)
    int restarts = -1;
  };
  void submit_chunk(const std::vector<ClaimedJob>& jobs, const std::vector<std::vector<std::size_t>>& tasks);
  /// A submission recorded as 'submitting' by a coordinator that died: did sbatch run?
  std::string find_lost_submission(const std::string& name);
  void detect_cluster();
  /// Final records of tasks that squeue no longer lists.
  std::map<slurm::TaskKey, slurm::TaskRecord> accounting(const std::set<std::string>& array_ids);
  void observe_files(Tracked& t);
  /// The exit code ("exit:signal") of an ended task from `scontrol show job`; "" if unknown.
  std::string scontrol_exit_code(const Tracked& t);
  WorkerExit ended(const Tracked& t, const std::string& state, const std::string& exit_code, bool with_verdict);
  double poll_interval_ = 0;

  CampaignStore& store_;
  std::string dir_;
  SlurmOptions options_;
  slurm::Commands commands_;
  std::map<std::int64_t, Tracked> tracked_;
  std::map<std::int64_t, std::string> submission_names_;  ///< submission id -> job name
  bool have_sacct_ = false;
  std::string jobcomp_path_;
  int max_array_ = 1000;
  double next_poll_ = 0;   ///< steady seconds
  double started_at_ = 0;  ///< steady seconds, for the polling-load report
};

}  // namespace beverloo
