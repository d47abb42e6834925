#include "sp_contact.h"

#include <cmath>

#include "harmonic_overlap.h"

namespace beverloo {

template <int D>
template <typename SpContact<D>::Friction kFriction>
TermOutput SpContact<D>::loop(const ParticleState<D>& s, VecArray<D>& f) {
  // species-pair tables: contact distance^2 and its inverse
  double sig2[2][2], inv_sig[2][2], eps[2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double sig = 0.5 * (s.sp.sigma[a] + s.sp.sigma[b]);
      sig2[a][b] = sig * sig;
      inv_sig[a][b] = 1.0 / sig;
      eps[a][b] = scale_with_sigma_ ? eps_ * sig : eps_;
    }
  double energy = 0, power = 0, max_ov = 0;
  const int n = s.size();
  for (int i = 0; i < n; ++i) {
    const Vec<D> xi = s.x[i];
    const int si = s.species[i];
    Vec<D> fi = Vec<D>::Zero();
    for (const int* p = list_.row_begin(i), *end = list_.row_end(i); p != end; ++p) {
      const int j = *p;
      const Vec<D> dx = xi - s.x[j];
      const double r2 = dx.squaredNorm();
      const int sj = s.species[j];
      if (r2 >= sig2[si][sj]) continue;
      const double r = std::sqrt(r2);
      double dU_dr;
      energy += HarmonicOverlap::energy(eps[si][sj], r, inv_sig[si][sj], dU_dr);
      const double ov = 1.0 - r * inv_sig[si][sj];
      max_ov = ov > max_ov ? ov : max_ov;
      Vec<D> fij = (-dU_dr / r) * dx;  // on i, along x_i - x_j (repulsive)
      if constexpr (kFriction != Friction::None) {
        if (rubs(i, j)) {
          const Vec<D> ff = friction_on<kFriction == Friction::Split>(s, i, j, dx, r);
          power += ff.dot(s.v[i] - s.v[j]);
          fij += ff;
        }
      }
      fi += fij;
      f[j] -= fij;
    }
    f[i] += fi;
  }
  max_overlap_ = max_ov;
  return {energy, power};
}

template <int D>
TermOutput SpContact<D>::accumulate(const ParticleState<D>& s, VecArray<D>& f) {
  if (!friction_on_ || !law_.active()) return loop<Friction::None>(s, f);
  return law_.split() ? loop<Friction::Split>(s, f) : loop<Friction::Full>(s, f);
}

template <int D>
void SpContact<D>::friction_forces(const ParticleState<D>& s, VecArray<D>& out) const {
  const int n = s.size();
  out.assign(n, Vec<D>::Zero());
  for (int i = 0; i < n; ++i) {
    for (const int* p = list_.row_begin(i), *end = list_.row_end(i); p != end; ++p) {
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
