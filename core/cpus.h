#pragma once
/// \file cpus.h
/// \brief How many CPUs this process may run on, and the check that threads (times workers)
/// do not ask for more: oversubscribed threads of one job slow it down and gain nothing.
#include <string>

namespace beverloo {

/// CPUs in this process's affinity mask (what Slurm or taskset grants), at least 1.
int usable_cpus();

/// Throws ConfigError naming `option` if workers x threads exceeds usable_cpus() or threads < 1.
void check_threads(const std::string& option, int threads, int workers = 1);

}  // namespace beverloo
