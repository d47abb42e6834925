#pragma once
/// \file vec_io.h
/// \brief Vector arrays to and from the flat row-major doubles that HDF5 datasets hold.
#include <string>
#include <vector>

#include "core/errors.h"
#include "../vec.h"

namespace beverloo {

template <int D>
std::vector<double> flatten(const VecArray<D>& a) {
  std::vector<double> out(a.size() * D);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int d = 0; d < D; ++d) out[i * D + d] = a[i][d];
  return out;
}

/// Throws IoError naming `what` if the sizes do not match.
template <int D>
void unflatten(const std::vector<double>& in, VecArray<D>& a, const std::string& what) {
  if (in.size() != a.size() * D) throw IoError("checkpoint: " + what + " has the wrong size");
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int d = 0; d < D; ++d) a[i][d] = in[i * D + d];
}

}  // namespace beverloo
