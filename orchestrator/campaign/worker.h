#pragma once
/// \file worker.h
/// \brief What executors start; never opens the campaign database, writes only job directories.
///  - `beverloo worker SPEC` (local executor): one attempt. Its lock on jobs/<dir>/lock is taken
///    by the executor before exec and inherited, so the job is locked for the worker's lifetime.
///  - `beverloo worker --manifest M --task I` (Slurm array task I): the attempts of line I of the
///    manifest, one after the other; the worker takes each job's lock itself.
/// Both write heartbeat.json while an attempt runs and outcome.json last. SIGINT, SIGTERM and
/// SIGUSR1 (Slurm's --signal=B:USR1@lead) make the running attempt checkpoint and stop.
#include <string>

namespace beverloo {
/// Returns the process exit code (the engine's codes of exit_codes.h).
int run_worker(const std::string& spec_path);
/// Returns 0 if every attempt of the task ended (done or failed: outcome files say which),
/// kInterrupted if a signal stopped it (unstarted attempts get an "interrupted" outcome too).
int run_worker_task(const std::string& manifest_path, int task_index);
}  // namespace beverloo
