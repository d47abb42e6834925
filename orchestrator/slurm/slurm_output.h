#pragma once
/// \file slurm_output.h
/// \brief Reading what Slurm's commands print (squeue, sacct, jobcomp/filetxt, sbatch), and the
/// reconciliation table: what an attempt's end means when its own result file does not say.
/// Pure functions over text, so that they are tested on recorded outputs (tests/data/slurm).
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/failures.h"

namespace beverloo::slurm {

/// One array task as some Slurm source reported it.
struct TaskRecord {
  std::string array_job_id;  ///< the array's id (what sbatch --parsable printed)
  int task = -1;             ///< array index; -1 for a job that is not an array element
  std::string state;         ///< base state word: RUNNING, CANCELLED ("CANCELLED by 0" -> CANCELLED), ...
  std::string reason;        ///< squeue's %r (empty elsewhere)
  std::string name;          ///< job name
  std::string exit_code;     ///< "7:0" (sacct, jobcomp, scontrol show job); empty from squeue
};

/// The format string squeue is called with; parse_squeue reads exactly these fields.
inline constexpr const char* kSqueueFormat = "%F|%K|%i|%T|%r|%j";
/// sacct's fields, for parse_sacct (with -X -n -P -D).
inline constexpr const char* kSacctFields = "JobID,JobName,State,ExitCode";

std::vector<TaskRecord> parse_squeue(const std::string& text);
/// Several records per task with -D (requeues): the last one wins. Pending ranges ("221_[7-9%2]")
/// are expanded into their tasks.
std::vector<TaskRecord> parse_sacct(const std::string& text);
/// jobcomp/filetxt lines (key=value pairs); the last record of a task wins (a requeue writes a
/// PENDING record first).
/// Also reads `scontrol show job -o` (the same Key=Value words, one job per line).
std::vector<TaskRecord> parse_jobcomp(const std::string& text);
/// sbatch --parsable prints "<id>" or "<id>;<cluster>"; throws if that is not what it printed.
std::string parse_sbatch_id(const std::string& out);
/// `scontrol show config` lines "Key = Value" as a map.
std::map<std::string, std::string> parse_config(const std::string& text);

/// "CANCELLED by 0" -> "CANCELLED", "CANCELLED+" -> "CANCELLED".
std::string base_state(const std::string& raw);
/// Slurm still owns the task (queued, running, ending, requeued, held, suspended).
bool in_flight(const std::string& state);
/// The task has ended for good (it will not run again unless someone requeues it).
bool terminal(const std::string& state);

/// The decision table (orchestration-peers.md 4.4) for an attempt whose task ended without a
/// result file of its own (or with one that says "interrupted"): the failure class to record.
/// COMPLETED without a result is `lost` (a rerun is free); FAILED is `killed` when the exit code
/// ("exit:signal") says SIGKILL (a free rerun, as locally), else `internal`; the
/// infrastructure ends (TIMEOUT, PREEMPTED, NODE_FAIL, BOOT_FAIL, DEADLINE) resume from the
/// checkpoint without using the retry budget; OUT_OF_MEMORY uses it (the same request would fail
/// again); CANCELLED by a user is `cancelled`: the job is not retried.
struct Verdict {
  FailureClass cls;
  std::string message;
};
Verdict verdict_for(const std::string& state, const std::string& exit_code = "");

/// Key of a task in lookups.
using TaskKey = std::pair<std::string, int>;
std::map<TaskKey, TaskRecord> by_task(const std::vector<TaskRecord>& records);
/// The record of array task (array, task): its own, else the array's meta record (task -1),
/// which stands for tasks not yet split off (an array cancelled while tasks were pending shows
/// them as one line with %K = N/A, and jobcomp writes no ArrayTaskId). nullptr if neither.
const TaskRecord* find_task(const std::map<TaskKey, TaskRecord>& records, const std::string& array, int task);

}  // namespace beverloo::slurm
