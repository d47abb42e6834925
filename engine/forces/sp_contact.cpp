#include "sp_contact.h"

#include <cmath>

#include "harmonic_overlap.h"

namespace beverloo {

template <int D>
void SpContact<D>::prepare(const ParticleState<D>& s) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double sig = 0.5 * (s.sp.sigma[a] + s.sp.sigma[b]);
      sig2_[a][b] = sig * sig;
      inv_sig_[a][b] = 1.0 / sig;
      eps_ab_[a][b] = normal_->energy_scale(eps_, sig);
    }
  list_.update_block_lists(s.species.data());
}

template <int D>
void SpContact<D>::friction_forces(const ParticleState<D>& s, VecArray<D>& out) const {
  const int n = s.size();
  out.assign(n, Vec<D>::Zero());
  for (int i = 0; i < n; ++i) {
    for (const int *p = list_.row_begin(i), *end = list_.row_end(i); p != end; ++p) {
      const int j = *p;
      const double sig = 0.5 * (s.sigma(i) + s.sigma(j));
      const Vec<D> dx = s.x[i] - s.x[j];
      if (dx.squaredNorm() >= sig * sig || !rubs(i, j)) continue;
      const double r = dx.norm();
      const Vec<D> ff = law_.split() ? friction_on<true>(s, i, j, dx, r) : friction_on<false>(s, i, j, dx, r);
      out[i] += ff;
      out[j] -= ff;
    }
  }
}

template class SpContact<2>;
template class SpContact<3>;

}  // namespace beverloo
