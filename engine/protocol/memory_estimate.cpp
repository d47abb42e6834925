#include "memory_estimate.h"

#include <sys/resource.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace beverloo {

std::uint64_t estimated_memory_bytes(const SimConfig& c) {
  const bool dp = c.is_dp();
  const double points = dp ? double(c.N) * c.dp.n_v : double(c.N);
  // per point: state ~ (3 D + 2) doubles; list ~ D doubles + cells, rows and ~10 (2D) or ~30 (3D)
  // neighbours of 4 bytes; terms' scratch and observables ~ 2 D doubles; a factor 2 for the
  // vectors' growth and what is not counted
  const double per_point = 2.0 * (8.0 * (3 * c.dimension + 2) + 8.0 * c.dimension + 16 +
                                  4.0 * (c.dimension == 3 ? 30 : 10) + 16.0 * c.dimension);
  // DP: the bodies (centroids) beside the vertices, and the per-vertex edge bounds
  const double bodies = dp ? 2.0 * 200.0 * c.N : 0.0;
  const double fixed = 64.0 * 1024 * 1024;  // binary, HDF5 buffers, the exit record's first reserve
  return static_cast<std::uint64_t>(points * per_point + bodies + fixed);
}

std::uint64_t available_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  std::uint64_t bytes = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : UINT64_MAX;
  // a container's limit (cgroup v2, then v1), when it is smaller
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    std::string text;
    if (in >> text && !text.empty() && text != "max") {
      try {
        const std::uint64_t limit = std::stoull(text);
        if (limit > 0 && limit < bytes) bytes = limit;
      } catch (const std::exception&) {
      }
    }
  }
  // the process's own address-space limit (ulimit -v, Slurm's --mem by some setups), less what
  // the process already maps (the binary, its libraries, the heap so far)
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    std::uint64_t mapped = 0;
    std::ifstream statm("/proc/self/statm");
    std::uint64_t pages_mapped = 0;
    if (statm >> pages_mapped && page > 0) mapped = pages_mapped * std::uint64_t(page);
    const std::uint64_t left = as.rlim_cur > mapped ? std::uint64_t(as.rlim_cur) - mapped : 0;
    if (left < bytes) bytes = left;
  }
  return bytes;
}

void check_memory(const SimConfig& c) {
  const std::uint64_t need = estimated_memory_bytes(c), have = available_memory_bytes();
  if (need <= have) return;
  char msg[256];
  std::snprintf(msg, sizeof msg,
                "%d %s need about %.1f GiB, more than the %.1f GiB this process may use (the machine's memory, a cgroup's "
                "memory.max, ulimit -v); lower N (or run it on a larger node)",
                c.N, c.is_dp() ? "polygons" : "particles", double(need) / (1ull << 30), double(have) / (1ull << 30));
  throw ConfigError("N", msg);
}

}  // namespace beverloo
