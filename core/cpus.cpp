#include "cpus.h"

#include <sched.h>

#include <thread>

#include "errors.h"

namespace beverloo {

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) {
    const int n = CPU_COUNT(&set);
    if (n > 0) return n;
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

void check_threads(const std::string& option, int threads, int workers) {
  if (threads < 1) throw ConfigError(option, "must be at least 1 (got " + std::to_string(threads) + ")");
  const int cpus = usable_cpus();
  if (static_cast<long>(threads) * workers > cpus)
    throw ConfigError(option, (workers > 1 ? std::to_string(workers) + " workers x " + std::to_string(threads) +
                                                 " threads = " + std::to_string(static_cast<long>(threads) * workers)
                                           : std::to_string(threads) + " threads") +
                                  " exceed the " + std::to_string(cpus) + " CPU(s) this process may use");
}

}  // namespace beverloo
