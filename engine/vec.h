#pragma once
/// \file vec.h
/// \brief Fixed-size vectors for 2D and 3D; the dimension is a template parameter everywhere.
#include <Eigen/Core>
#include <vector>

namespace beverloo {
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// One array of D-vectors (positions, velocities or forces of all particles).
template <int D>
using VecArray = std::vector<Vec<D>, Eigen::aligned_allocator<Vec<D>>>;

/// The axis along which gravity acts (gravity points to -axis): y in 2D, z in 3D.
template <int D>
inline constexpr int kUp = D - 1;
}  // namespace beverloo
