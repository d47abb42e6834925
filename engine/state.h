#pragma once
/// \file state.h
/// \brief The dynamic state of all particles as separate contiguous arrays (positions,
/// velocities, forces), plus the per-species constants they index into.
#include <array>
#include <cstdint>
#include <vector>

#include "vec.h"

namespace beverloo {

/// Per-species constants of the bidisperse mixture (0 = small, 1 = large).
struct Species {
  std::array<double, 2> sigma{};     ///< diameter
  std::array<double, 2> mass{};      ///< rho * reference area (2D) or volume (3D)
  std::array<double, 2> ref_size{};  ///< reference area (2D) or volume (3D): what Q counts
  /// a_avg (2D) or V_avg (3D) = mean of the two reference sizes (for Q' = Q a_eff / a_avg).
  double mean_ref_size() const { return 0.5 * (ref_size[0] + ref_size[1]); }
  static Species bidisperse(int dimension, double size_ratio);
};

template <int D>
struct ParticleState {
  VecArray<D> x;  ///< positions
  VecArray<D> v;  ///< velocities (during a force evaluation: the predicted velocity v~)
  VecArray<D> f;  ///< total force at the current positions and velocities
  std::vector<std::uint8_t> species;
  std::vector<double> inv_mass;
  std::vector<std::uint8_t> exited;  ///< counted as exited, not yet reinjected
  std::int64_t step = 0;             ///< steps since gravity was switched on
  Species sp;

  int size() const { return static_cast<int>(x.size()); }
  void resize(int n) {
    x.assign(n, Vec<D>::Zero());
    v.assign(n, Vec<D>::Zero());
    f.assign(n, Vec<D>::Zero());
    species.assign(n, 0);
    inv_mass.assign(n, 0.0);
    exited.assign(n, 0);
  }
  /// Item `from` takes slot `to` (its old slot keeps a copy): with truncate, how a draining
  /// hopper takes an item out in O(1) (swap the last into its place, drop the last).
  void move(int from, int to) {
    x[to] = x[from];
    v[to] = v[from];
    f[to] = f[from];
    species[to] = species[from];
    inv_mass[to] = inv_mass[from];
    exited[to] = exited[from];
  }
  /// Takes item i out: the last item takes its place (indices above i are kept but for the last).
  void remove_swapping_last(int i) {
    const int last = size() - 1;
    move(last, i);
    truncate(last);
  }
  /// Keeps the first n items (n <= size()); no reallocation.
  void truncate(int n) {
    x.resize(n);
    v.resize(n);
    f.resize(n);
    species.resize(n);
    inv_mass.resize(n);
    exited.resize(n);
  }
  double sigma(int i) const { return sp.sigma[species[i]]; }
  double mass(int i) const { return sp.mass[species[i]]; }
  /// Kinetic energy sum M v^2 / 2.
  double kinetic_energy() const {
    double k = 0;
    for (int i = 0; i < size(); ++i) k += 0.5 * mass(i) * v[i].squaredNorm();
    return k;
  }
};

}  // namespace beverloo
