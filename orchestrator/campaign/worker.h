#pragma once
/// \file worker.h
/// \brief `beverloo worker SPEC`: runs one job attempt in its job directory. Never opens the
/// campaign database. Its lock on jobs/<dir>/lock is taken by the executor before exec and is
/// inherited, so the job is locked for exactly the worker's lifetime.
#include <string>

namespace beverloo {
/// Returns the process exit code (the engine's codes of exit_codes.h).
int run_worker(const std::string& spec_path);
}  // namespace beverloo
