#include "reinjector.h"

#include <algorithm>
#include <cmath>

#include "../units.h"

namespace beverloo {

template <int D>
bool Reinjector<D>::is_free(const ParticleState<D>& s, int i, const Vec<D>& p, int touching,
                            const NeighborList<D>* near) const {
  if (!hopper_.contains(p) || p[kUp<D>] < 0) return false;
  const double ri = 0.5 * s.sigma(i);
  for (int w = 0; w < Hopper<D>::kNumWalls; ++w)
    if ((p - hopper_.nearest_point(w, p)).squaredNorm() < ri * ri) return false;
  const int n = s.size();
  auto overlaps = [&](int k) {
    if (k == i) return false;
    const double sig = 0.5 * (s.sigma(i) + s.sigma(k));
    // the touched particle sits at exactly sigma_ik: allow for the rounding of that placement
    const double tol = k == touching ? 1.0 - 1e-12 : 1.0;
    return (p - s.x[k]).squaredNorm() < sig * sig * tol;
  };
  // With a list: only the particles it finds near p (the largest contact distance of i is its
  // reach), then the extra test.
  if (near) {
    bool free = true;
    const double reach = 0.5 * (s.sigma(i) + std::max(s.sp.sigma[0], s.sp.sigma[1]));
    if (near->for_each_near(p, reach, [&](int k) { free = free && !overlaps(k); }))
      return free && (!extra_test_ || extra_test_(i, p));
  }
  // Else every particle is tested (N per tried spot, most of them far away): a branchless pass over
  // a chunk at a time, with the exact test above only in a chunk where something is within
  // contact reach (its threshold is never below the exact test's, so nothing is missed).
  double reach2[2];
  for (int sp = 0; sp < 2; ++sp) {
    const double sig = 0.5 * (s.sigma(i) + s.sp.sigma[sp]);
    reach2[sp] = sig * sig;
  }
  const double* X = s.x.data()->data();
  const std::uint8_t* species = s.species.data();
  constexpr int kChunk = 16;
  for (int k0 = 0; k0 < n; k0 += kChunk) {
    const int k1 = std::min(n, k0 + kChunk);
    int near = 0;
    for (int k = k0; k < k1; ++k) {
      double d2 = 0;
      for (int d = 0; d < D; ++d) {
        const double u = p[d] - X[k * D + d];
        d2 += u * u;
      }
      near |= d2 < reach2[species[k]];
    }
    if (near)
      for (int k = k0; k < k1; ++k)
        if (overlaps(k)) return false;
  }
  return !extra_test_ || extra_test_(i, p);
}

template <int D>
bool Reinjector<D>::reinject(ParticleState<D>& s, int i, Rng& rng, const std::vector<std::uint8_t>& pile,
                            const NeighborList<D>* near) {
  const int n = s.size();
  auto in_pile = [&](int k) { return k != i && pile[k]; };
  double top = -INFINITY;
  for (int k = 0; k < n; ++k)
    if (in_pile(k)) top = std::max(top, s.x[k][kUp<D>]);
  candidates_.clear();
  for (int k = 0; k < n; ++k)
    if (in_pile(k) && s.x[k][kUp<D>] >= top - p_.top_band) candidates_.push_back(k);

  for (int attempt = 0; attempt < p_.max_attempts && !candidates_.empty(); ++attempt) {
    const int c = candidates_[rng.below(candidates_.size())];
    Vec<D> dir;
    if constexpr (D == 2) {
      const double phi = rng.uniform() * units::pi;  // upper half circle
      dir << std::cos(phi), std::sin(phi);
    } else {
      const double z = rng.uniform();  // uniform on the upper hemisphere (Archimedes)
      const double phi = rng.uniform() * 2 * units::pi;
      const double r = std::sqrt(1 - z * z);
      dir << r * std::cos(phi), r * std::sin(phi), z;
    }
    const Vec<D> p = s.x[c] + 0.5 * (s.sigma(i) + s.sigma(c)) * dir;
    if (!is_free(s, i, p, c, near)) continue;
    s.x[i] = p;
    s.v[i] = s.v[c];
    s.exited[i] = 0;
    return true;
  }
  // Fallback (no pile yet, e.g. while the initial column falls, or no free spot): a random
  // lateral position, just above the highest pile particle in that vertical column (or the
  // floor), moving like it, lifted until it overlaps nothing. Particles in the air are never
  // the base of a placement, so successive placements cannot stack into a tower. The lift has
  // no cap: above every particle the spot is free, so the loop ends (a cap of 64 half
  // diameters hung forever under a tall falling column of hard particles).
  const double ri = 0.5 * s.sigma(i);
  const double half = hopper_.half_width() - ri;
  for (;;) {
    Vec<D> p = Vec<D>::Zero();
    do {
      for (int d = 0; d < D - 1; ++d) p[d] = rng.uniform(-half, half);
    } while (Hopper<D>::lateral(p) >= half);
    p[0] += hopper_.lateral_centre();  // 0 unless a funnel wall is vertical (2D): no bit changes
    double column_top = hopper_.funnel_top() + ri;
    int below = -1;
    for (int k = 0; k < n; ++k) {
      if (!in_pile(k)) continue;
      Vec<D> d = s.x[k] - p;
      d[kUp<D>] = 0;
      const double sig = 0.5 * (s.sigma(i) + s.sigma(k));
      if (d.squaredNorm() < sig * sig && s.x[k][kUp<D>] + sig > column_top) {
        column_top = s.x[k][kUp<D>] + sig;
        below = k;
      }
    }
    for (int lift = 0;; ++lift) {
      p[kUp<D>] = column_top + lift * ri;
      if (is_free(s, i, p, below, near)) {
        s.x[i] = p;
        s.v[i] = below >= 0 ? s.v[below] : Vec<D>::Zero();
        s.exited[i] = 0;
        return false;
      }
    }
  }
}

// The constants of the authors' rule, in small diameters sigma_s (their code's length unit:
// YUXUANCHENG/DPM_OMP, commit 1258ab0, src/NVE.h, DPMhopperSimulator::addBack, getMaxHight,
// getVatMaxHeight; docs/authors-model.md section 3).
namespace lanes {
constexpr double kSpacing = 2.0;        // lateral distance between lanes ("* 2" in displace)
constexpr int kSafeZone = 2;            // lanes left out near the walls ("safeZone = 2")
constexpr double kHalfWindow = 1.5;     // a particle belongs to a lane within this ("y +- 1.5")
constexpr double kDropHeight = 1.0;     // centre this far above the lane's top ("maxHight - 1")
constexpr double kFreeFallHeight = 1.5; // speed reduced by free fall over this ("2*g*1.5/16")
// "b < 5e-3" in code units; the code's time unit is t0/19.596 (authors-model.md section 1)
constexpr double kFreeFallBelowRate = 5e-3 * 19.596;  // 1/t0
constexpr double kSideways = 0.1;       // sideways speed over downward speed ("0.1*v")
}  // namespace lanes

template <int D>
int Reinjector<D>::lanes(const ParticleState<D>& s) const {
  const double small = s.sp.sigma[0];
  const int n = static_cast<int>(std::floor(2 * hopper_.half_width() / (lanes::kSpacing * small))) - lanes::kSafeZone;
  return std::max(n, 1);
}

template <int D>
bool Reinjector<D>::reinject_in_lane(ParticleState<D>& s, int i, std::int64_t placement, double drag_rate,
                                    const NeighborList<D>* near) {
  const double small = s.sp.sigma[0];
  const int k_lane = static_cast<int>(placement % lanes(s));
  // 0, -1, +1, -2, +2, ... lane spacings from the axis (the code's round((k + 1e-4) / 2) * (-1)^k)
  // (about the container's centre: 0 unless a funnel wall is vertical, then no bit changes)
  const double offset = hopper_.lateral_centre() +
                        std::round((k_lane + 1e-4) / 2.0) * (k_lane % 2 ? -1.0 : 1.0) * lanes::kSpacing * small;
  const int n = s.size();
  auto in_lane = [&](int k) {
    return k != i && !s.exited[k] && std::fabs(s.x[k][0] - offset) < lanes::kHalfWindow * small;
  };
  int highest = -1;
  for (int k = 0; k < n; ++k)
    if (in_lane(k) && (highest < 0 || s.x[k][kUp<D>] > s.x[highest][kUp<D>])) highest = k;
  const double lane_top =
      highest >= 0 ? s.x[highest][kUp<D>] + 0.5 * s.sigma(highest) : hopper_.funnel_top();
  Vec<D> p = Vec<D>::Zero();
  p[0] = offset;
  p[kUp<D>] = lane_top + lanes::kDropHeight * small;
  // the code places without a check; a soft spot taken by a wall or a stretched polygon is
  // not ours to overlap (a stiff contact would blow up), so lift in half-diameter steps
  const double ri = 0.5 * s.sigma(i);
  bool lifted = false;
  while (!is_free(s, i, p, -1, near)) {
    p[kUp<D>] += ri;
    lifted = true;
  }
  // the velocity: the nearest particle below the new one in its lane
  int below = -1;
  for (int k = 0; k < n; ++k)
    if (in_lane(k) && s.x[k][kUp<D>] < p[kUp<D>] && (below < 0 || s.x[k][kUp<D>] > s.x[below][kUp<D>])) below = k;
  const double v_down = below >= 0 ? -s.v[below][kUp<D>] : 0.0;
  double v_new = v_down;
  const double fall = 2 * lanes::kFreeFallHeight * small;  // 2 g h with g = 1
  if (drag_rate < lanes::kFreeFallBelowRate && v_down * v_down - fall > 0) v_new = std::sqrt(v_down * v_down - fall);
  s.x[i] = p;
  s.v[i] = Vec<D>::Zero();
  s.v[i][kUp<D>] = -v_new;
  // the code alternates the sign with the particle's number: its id here (the slot changes)
  s.v[i][0] = lanes::kSideways * v_down * (s.id[i] % 2 ? -1.0 : 1.0);
  s.exited[i] = 0;
  return !lifted;
}

template class Reinjector<2>;
template class Reinjector<3>;

}  // namespace beverloo
