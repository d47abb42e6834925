#pragma once
/// \file authors_dp_set.h
/// \brief The DP set of the authors' code (DPM_OMP `frictionless` @ 1258ab0: kl = 1, ka = 100,
/// kb = 0.01, kint = 10, cutoff 0.2, a vertex l0 wide against the walls) in our units, derived
/// with file and line in docs/authors-model.md section 3a. One place for the values that the
/// bench cases and the tests use; the shipped sweeps spell them out (a sweep is a file).
#include <string>

#include "../config.h"

namespace beverloo {

/// Sets c's DP shape, contact and wall terms to the authors' code's (c.model chooses the
/// smooth or rough contact); leaves everything else (N, drag, friction, ...) as it is.
inline void use_authors_dp_set(SimConfig& c) {
  c.dp.K_l = 88.29;        // 416.67 x 0.2119 kl (small)
  c.dp.K_l_large = 123.62; // 416.67 x 0.2967 kl (large)
  c.dp.K_a = 3055.8;       // ka / a0 x 24.0 (small)
  c.dp.K_a_large = 1559.1; // (large)
  c.dp.K_b = 0.02626;      // 2.626 kb
  c.dp.wall_width = 1;     // a vertex l0 wide against walls
  c.dp.wall_thickness = 1; // the floor l0 thick, its lip a bead l0 wide (hopper2D.cpp 1682-1687)
  c.E_w = 11.574;          // 1 code energy
  if (c.model == "dp_smooth") {
    c.dp.E_c = 231.48;      // kint (1 - d/delta)^2: E_c = 2 kint
    c.dp.E_c_vertex = 115.74;  // corners: 0.5 kint (1 - r/delta)^2
    c.dp.contact_width = 0.2;
  } else {
    c.dp.E_c = 115.74;  // vertex disks: 0.5 kint (1 - r/l0)^2
  }
}

}  // namespace beverloo
