// How a DP polygon ended in a wall: a job resumed from its checkpoint and stepped one step at a
// time; the vertices of one polygon (positions and velocities) are kept for the last `keep`
// steps and printed when containment fails (or at t_stop), with every vertex's distance from
// the left and right orifice edges' lip centres. Behind docs/validation.md's "soft polygons at
// the orifice lip".
// Usage: dp_trace_polygon JOB.json CHECKPOINT.h5 polygon t_stop keep [print_every]
#include <cstdio>
#include <deque>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/config.h"
#include "engine/dp/dp_system.h"
#include "engine/protocol/hopper_run.h"
#include "resumed_run.h"

using namespace beverloo;

namespace {
struct Frame {
  std::int64_t step;
  double t;
  std::vector<Vec<2>> x, v;
};

void print_frame(const Frame& f, double half_w) {
  std::printf("step %lld t %.6f\n", static_cast<long long>(f.step), f.t);
  for (std::size_t k = 0; k < f.x.size(); ++k)
    std::printf("  v%2zu x % .5f % .5f  v % .4f % .4f  |x|-w/2 % .5f\n", k, f.x[k][0], f.x[k][1], f.v[k][0],
                f.v[k][1], std::abs(f.x[k][0]) - half_w);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s JOB.json CHECKPOINT.h5 polygon t_stop keep [print_every]\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1]);
  SimConfig c = SimConfig::from_json(nlohmann::json::parse(in));
  const int polygon = std::atoi(argv[3]);
  const double t_stop = std::atof(argv[4]);
  const std::size_t keep = static_cast<std::size_t>(std::atol(argv[5]));
  const int print_every = argc > 6 ? std::atoi(argv[6]) : 1;
  auto resumed = diagnostics::resumed_run(c, argv[2], "dp_trace_polygon");
  HopperRun<2>& run = *resumed;
  DpSystem& dp = *run.dp();
  const PolygonSet& p = dp.polygons();
  std::vector<int> mine;
  for (int i = 0; i < dp.verts().size(); ++i)
    if (p.owner[i] == polygon) mine.push_back(i);
  std::printf("polygon %d: vertices %d..%d, dt %.4g, t %.4f\n", polygon, mine.front(), mine.back(),
              run.time_step().dt, run.time());
  std::deque<Frame> frames;
  const double half_w = 0.5 * c.w;
  try {
    while (run.time() < t_stop) {
      run.advance(1);
      dp.check_vertices(run.time());
      Frame f{run.state().step, run.time(), {}, {}};
      for (int i : mine) {
        f.x.push_back(dp.verts().x[i]);
        f.v.push_back(dp.verts().v[i]);
      }
      frames.push_back(std::move(f));
      if (frames.size() > keep) frames.pop_front();
    }
    std::printf("reached t_stop\n");
  } catch (const std::exception& e) {
    std::printf("stopped: %s\n", e.what());
  }
  for (std::size_t k = 0; k < frames.size(); ++k)
    if (k % print_every == 0 || k + 1 == frames.size()) print_frame(frames[k], half_w);
  return 0;
}
