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
  /// Each item's identity (0 .. N-1 at placement), carried along when items are reordered (an
  /// SP model sorts its particles by cell; a draining hopper swaps the last into a taken-out
  /// slot): what exit records and trajectories name, where the index is only a storage slot.
  std::vector<std::int32_t> id;
  std::int64_t step = 0;  ///< steps since gravity was switched on
  Species sp;

  int size() const { return static_cast<int>(x.size()); }
  void resize(int n) {
    x.assign(n, Vec<D>::Zero());
    v.assign(n, Vec<D>::Zero());
    f.assign(n, Vec<D>::Zero());
    species.assign(n, 0);
    inv_mass.assign(n, 0.0);
    exited.assign(n, 0);
    id.resize(n);
    for (int i = 0; i < n; ++i) id[i] = i;
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
    id[to] = id[from];
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
    id.resize(n);
  }
  /// Reorders the items: new slot k holds old item order[k] (a permutation of 0 .. size-1).
  /// scratch holds the copies between calls, so that a reorder allocates nothing once warm.
  void permute(const std::vector<int>& order, ParticleState& scratch) {
    const int n = size();
    scratch.x.resize(n);
    scratch.v.resize(n);
    scratch.f.resize(n);
    scratch.species.resize(n);
    scratch.inv_mass.resize(n);
    scratch.exited.resize(n);
    scratch.id.resize(n);
    for (int k = 0; k < n; ++k) {
      const int i = order[k];
      scratch.x[k] = x[i];
      scratch.v[k] = v[i];
      scratch.f[k] = f[i];
      scratch.species[k] = species[i];
      scratch.inv_mass[k] = inv_mass[i];
      scratch.exited[k] = exited[i];
      scratch.id[k] = id[i];
    }
    x.swap(scratch.x);
    v.swap(scratch.v);
    f.swap(scratch.f);
    species.swap(scratch.species);
    inv_mass.swap(scratch.inv_mass);
    exited.swap(scratch.exited);
    id.swap(scratch.id);
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
