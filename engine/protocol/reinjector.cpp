#include "reinjector.h"

#include <algorithm>
#include <cmath>

#include "../units.h"

namespace beverloo {

template <int D>
bool Reinjector<D>::is_free(const ParticleState<D>& s, int i, const Vec<D>& p, int touching) const {
  if (!hopper_.contains(p) || p[kUp<D>] < 0) return false;
  const double ri = 0.5 * s.sigma(i);
  for (int w = 0; w < Hopper<D>::kNumWalls; ++w)
    if ((p - hopper_.nearest_point(w, p)).squaredNorm() < ri * ri) return false;
  const int n = s.size();
  for (int k = 0; k < n; ++k) {
    if (k == i) continue;
    const double sig = 0.5 * (s.sigma(i) + s.sigma(k));
    // the touched particle sits at exactly sigma_ik: allow for the rounding of that placement
    const double tol = k == touching ? 1.0 - 1e-12 : 1.0;
    if ((p - s.x[k]).squaredNorm() < sig * sig * tol) return false;
  }
  return !extra_test_ || extra_test_(i, p);
}

template <int D>
bool Reinjector<D>::reinject(ParticleState<D>& s, int i, Rng& rng, const std::vector<std::uint8_t>& pile) {
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
    if (!is_free(s, i, p, c)) continue;
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
      if (is_free(s, i, p, below)) {
        s.x[i] = p;
        s.v[i] = below >= 0 ? s.v[below] : Vec<D>::Zero();
        s.exited[i] = 0;
        return false;
      }
    }
  }
}

template class Reinjector<2>;
template class Reinjector<3>;

}  // namespace beverloo
