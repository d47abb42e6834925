#pragma once
/// \file drag.h
/// \brief Viscous drag from the background fluid, F_m = -zeta v_m; power -zeta |v|^2 <= 0.
#include "force_term.h"

namespace beverloo {

template <int D>
class Drag final : public ForceTerm<D> {
 public:
  explicit Drag(double zeta) : zeta_(zeta) {}
  std::string_view name() const override { return "drag"; }
  void set_enabled(bool on) { on_ = on; }
  double zeta() const { return zeta_; }
  TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) override {
    if (!on_ || zeta_ == 0) return {};
    double power = 0;
    const int n = s.size();
    for (int i = 0; i < n; ++i) {
      f[i] -= zeta_ * s.v[i];
      power -= zeta_ * s.v[i].squaredNorm();
    }
    return {0, power};
  }

 private:
  double zeta_;
  bool on_ = true;
};

}  // namespace beverloo
