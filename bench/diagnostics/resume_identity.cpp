// Whether a run resumed from a checkpoint follows the uninterrupted run bit for bit, from a
// real job's checkpoint: run A advances n + m steps; run B advances n, saves a checkpoint, and a
// fresh run loads it and advances m. Prints the first step (checked every `every` steps) at
// which the states differ, and the largest position difference then.
// Usage: resume_identity JOB.json CHECKPOINT.h5 n m [every]
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "engine/config.h"
#include "engine/dp/dp_system.h"
#include "engine/protocol/hopper_run.h"
#include "resumed_run.h"

using namespace beverloo;

namespace {
const ParticleState<2>& points(HopperRun<2>& run) { return run.dp() ? run.dp()->verts() : run.state(); }

/// Largest |x_a - x_b| over the points (vertices for DP), and whether every bit is the same.
double difference(HopperRun<2>& a, HopperRun<2>& b, bool& identical) {
  const ParticleState<2>&pa = points(a), &pb = points(b);
  double worst = 0;
  identical = pa.size() == pb.size();
  if (!identical) return 0;
  for (int i = 0; i < pa.size(); ++i) {
    if (identical && (pa.x[i] != pb.x[i] || pa.v[i] != pb.v[i])) {
      identical = false;
      std::printf("first differing point %d at (%.6f %.6f)\n", i, pa.x[i][0], pa.x[i][1]);
    }
    worst = std::max(worst, (pa.x[i] - pb.x[i]).norm());
  }
  return worst;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s JOB.json CHECKPOINT.h5 n m [every]\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1]);
  const SimConfig c = SimConfig::from_json(nlohmann::json::parse(in));
  const std::int64_t n = std::atoll(argv[3]), m = std::atoll(argv[4]);
  const std::int64_t every = argc > 5 ? std::atoll(argv[5]) : 1;
  // each run resumes as `simulate --resume` does (diagnostics::resumed_run)
  auto a = diagnostics::resumed_run(c, argv[2], "resume_identity_a");
  auto b = diagnostics::resumed_run(c, argv[2], "resume_identity_b");
  a->advance(n);
  b->advance(n);
  const std::filesystem::path mid =
      std::filesystem::temp_directory_path() / ("resume_identity_mid." + std::to_string(::getpid()) + ".h5");
  b->save_checkpoint(mid.string());
  auto r = diagnostics::resumed_run(c, mid, "resume_identity_r");
  std::filesystem::remove(mid);
  bool identical = true;
  difference(*a, *r, identical);
  std::printf("at the checkpoint (step %lld): %s\n", static_cast<long long>(a->state().step),
              identical ? "identical" : "DIFFERENT");
  for (std::int64_t k = 0; k < m; k += every) {
    const std::int64_t s = std::min(every, m - k);
    a->advance(s);
    r->advance(s);
    const double worst = difference(*a, *r, identical);
    if (!identical) {
      std::printf("first difference by step %lld (%lld after the checkpoint): largest |dx| %.3g; list builds %lld and %lld\n",
                  static_cast<long long>(a->state().step), static_cast<long long>(k + s), worst,
                  static_cast<long long>(a->neighbor_builds()), static_cast<long long>(r->neighbor_builds()));
      return 1;
    }
  }
  std::printf("identical for %lld steps after the checkpoint\n", static_cast<long long>(m));
  return 0;
}
