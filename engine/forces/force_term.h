#pragma once
/// \file force_term.h
/// \brief One interface for every force term, conservative or dissipative: accumulate() adds
/// the term's forces and returns its energy and the power it does on the particles. A
/// conservative term returns its potential energy; a dissipative one returns energy 0 and
/// power = sum_i F_i . v_i, which must never be positive (tested).
#include <string_view>

#include "../state.h"

namespace beverloo {

struct TermOutput {
  double energy = 0;  ///< potential energy (conservative terms)
  double power = 0;   ///< sum_i F_i . v_i of the dissipative part (<= 0)
};

template <int D>
class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  virtual std::string_view name() const = 0;
  /// Adds forces of this term at the state's positions (and velocities) to f.
  virtual TermOutput accumulate(const ParticleState<D>& s, VecArray<D>& f) = 0;
};

}  // namespace beverloo
