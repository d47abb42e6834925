#pragma once
/// \file config.h
/// \brief The typed configuration of one hopper-flow job, with every default of physics.md.
///
/// The default member initialisers below are the one defaults table of the engine: each
/// "Decision:" of shared/spec/physics.md lives here and nowhere else. All values are in the
/// code units of units.h unless a name says otherwise (*_deg: degrees; *_steps: time steps).
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "core/errors.h"

namespace beverloo {

/// FIRE minimiser constants (Bitzek et al. 2006, physics.md section 6.2).
struct FireParams {
  double alpha0 = 0.1;
  double f_inc = 1.1;
  double f_dec = 0.5;
  double f_alpha = 0.99;
  int n_min = 5;
  double dt_max_factor = 10.0;  ///< dt_max = dt_max_factor * dt
  double force_tol = 1e-6;      ///< stop when max |F| (code units) falls below this
  std::int64_t max_iter = 2000000;
  /// FIRE removes the initial overlaps with E = min(E_sp, this): with E_sp = 1e5 the random
  /// placement's overlaps push harder than the walls (E_w = 1e4) can hold and particles end up
  /// outside. The minimum FIRE reaches (no overlaps) does not depend on this stiffness.
  double max_pair_stiffness = 100.0;
};

/// Run controls: when to stop, what to write. Times in t0.
struct RunControls {
  double t_max = 2000.0;             ///< hard limit on flowing time after gravity is switched on
  double target_rel_err = 0.02;      ///< stop when SE(Q)/Q falls below this
  double t_clog = 100.0;             ///< no exit for this long: clogged
  /// Stop early (status "unreachable") when the error's fall predicts that t_max will not bring
  /// SE(Q)/Q to the target (HopperRun::run); off by default.
  bool stop_unreachable = false;
  /// No stopping rule but the clog's ends the run before this flowing time; above t_max it is
  /// the time limit. A finished job is given more flow time by the job that differs only here.
  double min_time = 0.0;
  double min_transient = 20.0;       ///< transient removed is at least this long
  double min_window = 100.0;         ///< the measurement window is at least this long before stopping
  double check_interval = 10.0;      ///< how often the stopping rule is evaluated
  double rate_bin = 1.0;             ///< bin width of the exit-rate series (MSER, blocking)
  double checkpoint_interval = 100.0;  ///< simulated time between checkpoints (0: none)
  std::int64_t trajectory_every_steps = 0;  ///< H5MD frame every K steps (0: no trajectory)
};

/// Reinjection of exited particles on top of the pile (physics.md 6.4).
struct ReinjectionParams {
  double drop_depth_diameters = 2.0;  ///< reinject once this many own diameters below the orifice
  double top_band = 3.0;              ///< candidates to touch: within this of the highest pile particle
  int max_attempts = 500;             ///< random placements tried before the fallback
  /// "pile": touch a topmost pile particle (physics.md 6.4, the text); "lanes": the authors'
  /// code's rule, dropped above the top of one of a set of fixed vertical lanes (reinjector.h)
  std::string rule = "pile";
};

/// A draining hopper (reinject = false, physics.md 9): when to stop and how dN/dt = -c0 sqrt(N)
/// is fitted (engine/protocol/drain_fit.h).
struct DrainParams {
  int stop_below = 0;     ///< the run ends once at most this many particles remain in the hopper
  int fit_skip = 100;     ///< exits left out at each end: the first n, and those with fewer than n left
  int block_exits = 10;   ///< exits per rate block of the fit
};

/// Observables of physics.md section 7.
struct ObservableParams {
  double sample_interval = 0.1;  ///< t0 between samples of profile, density and forces
  double block_length = 5.0;     ///< t0 per accumulation block (transient cut, errors)
  double profile_dh = 0.25;      ///< height spacing of v_g(h)
  double profile_h_max = 30.0;   ///< largest height of v_g(h) above the orifice
  double kernel_width = 1.0;     ///< Gaussian coarse-graining width (sigma_avg)
};

/// Deformable-particle (DP) model constants (physics.md 4); used by the models dp_smooth and
/// dp_rough only. Energies in g rho sigma_avg^2 units as in the paper (K_a = k_a, ...).
struct DpParams {
  int n_v = 16;       ///< vertices per polygon
  double K_a = 1e4;   ///< area stiffness (area nearly conserved for K_a >= 1e4)
  double K_l = 10.0;  ///< segment-length (perimeter) stiffness
  double K_b = 0.1;   ///< bending stiffness (K_b > 1e2: rigid limit)
  double E_c = 1e4;   ///< vertex-vertex (rough) or vertex-edge (smooth) contact stiffness
  /// Smooth DP: width of an edge's circulo-line in units of the reference edge length l0
  /// (physics.md 4: 0.1; the authors' code runs 0.2, docs/authors-model.md).
  double contact_width = 0.1;
  // Forms the authors' code has and the paper's text does not (docs/authors-model.md); each
  // unset is the text's model, bit for bit.
  /// Perimeter and area stiffness of the large species (unset: K_l, K_a). The code's perimeter
  /// force carries a species factor (K_l large/small = 1.40), its area term is (ka/2) a0 (a/a0 -
  /// 1)^2 (K_a = ka/a0 per species).
  std::optional<double> K_l_large, K_a_large;
  /// Smooth DP: energy scale of the vertex-vertex contacts at polygon corners (unset: E_c; the
  /// code: half the edges', 0.5 kint against kint).
  std::optional<double> E_c_vertex;
  /// Diameter of a vertex against the walls and the orifice corners, in l0 (unset: the contact
  /// diameter, dp.contact_width l0 smooth or l0 rough; the code: 1).
  std::optional<double> wall_width;
  /// Thickness of the funnel walls in l0 of the small species (0: walls are lines, the text's
  /// model; the authors' code: a floor l0 thick whose end at the orifice is a bead l0 wide,
  /// engine/geometry/funnel_cores.h).
  double wall_thickness = 0;
  double K_l_of(int species) const { return species == 1 && K_l_large ? *K_l_large : K_l; }
  double K_a_of(int species) const { return species == 1 && K_a_large ? *K_a_large : K_a; }
};

struct SimConfig {
  // --- model and system -------------------------------------------------------------
  /// "sp" (soft particles, 2D/3D), "dp_smooth" (deformable polygons with circulo-line edges,
  /// nearly frictionless) or "dp_rough" (deformable polygons with vertex disks), both 2D.
  std::string model = "sp";
  int dimension = 2;
  int N = 0;                 ///< 0: default (1600 in 2D, 6400 in 3D)
  double size_ratio = 1.4;   ///< sigma_l / sigma_s
  double W = 0;              ///< container width (2D) or diameter (3D); 0: 50 (2D) / 25 (3D)
  double w = 0;              ///< orifice width (2D) or diameter (3D); required
  double theta_w_left_deg = 90.0;   ///< funnel angle from gravity, left wall (2D)
  double theta_w_right_deg = 90.0;  ///< funnel angle from gravity, right wall (2D)
  // --- interactions -------------------------------------------------------------------
  double E_sp = 100.0;  ///< pair stiffness, units g rho sigma^(d+1)
  /// The SP pairs' normal law, a row of the registry in forces/contact_laws.cpp: "energy"
  /// (every pair the energy scale E_sp, the paper's text), "force" (E_sp sigma_mn, a constant
  /// force scale as in the authors' code, docs/authors-model.md), "hertz", ...
  std::string sp_contact_law = "energy";
  double E_w = 1e4;     ///< wall stiffness
  double zeta = -1;     ///< viscous drag; required
  double mu = -1;       ///< kinetic friction; required
  /// Kinetic friction split along the contact normal and the tangent (physics.md 10): unset,
  /// each is mu (the text's full relative velocity); the authors' code runs mu_n = 0.
  std::optional<double> mu_n, mu_t;
  /// Drag as a rate times the mass, F = -drag_rate M v (per vertex: its mass), in 1/t0, added
  /// to zeta's F = -zeta v. The authors' code runs this form (physics.md 10).
  double drag_rate = 0;
  double gravity = 1.0; ///< in units of g (tests switch it off)
  DpParams dp;          ///< DP models only
  // --- numerics -----------------------------------------------------------------------
  std::optional<double> dt;  ///< unset: "auto"
  double skin = 0;           ///< Verlet-list skin (not physics; only speed); 0: 0.3 (SP), 0.1 (DP, over vertices)
  /// A relative pair overlap 1 - r/sigma_mn above this stops the run as unstable. Half a
  /// diameter (0.5) is exceeded physically at E_sp = 100, N = 1600: without wall friction the
  /// pressure grows with depth, and force chains at the bottom of the pile reach 0.5-0.6
  /// (drag only) and 0.6-0.95 (friction only, mu = sqrt 10), measured with small relative
  /// velocities. So the default only catches centres that nearly coincide; NaN, escapes and
  /// wall crossings are caught separately.
  double max_overlap = 0.99;
  // --- protocol -----------------------------------------------------------------------
  double initial_packing_fraction = 0.5;  ///< random placement density before FIRE
  bool reinject = true;                   ///< false: draining hopper (physics.md 9)
  std::optional<std::uint64_t> seed;      ///< unset: derived from the parameters
  int replica = 0;                        ///< changes the derived seed, nothing else
  FireParams fire;
  RunControls run;
  ReinjectionParams reinjection;
  DrainParams drain;
  ObservableParams observables;

  /// Parse a job file. Unknown fields are errors (a typo must not silently become a default).
  static SimConfig from_json(const nlohmann::json& j);
  /// Fully resolved parameters, defaults filled in, keys sorted: the job's identity.
  nlohmann::json to_json() const;
  /// The canonical job without the settings that cannot change a finished result (the rows of
  /// engine/parameters.cpp with in_key = false): what the job key hashes.
  nlohmann::json key_json() const;
  /// The canonical job without its stopping rules (the rows with stop_rule = true): equal for two
  /// jobs that follow one trajectory and differ only in when they stop.
  nlohmann::json trajectory_json() const;
  /// Fills the dimension-dependent defaults and checks every field; throws ConfigError.
  void resolve_and_validate();
  /// The seed: explicit, or a hash of the canonical physics and protocol parameters (run
  /// controls, skin and max_overlap excluded: they must not change the trajectory).
  std::uint64_t effective_seed() const;

  bool is_dp() const { return model == "dp_smooth" || model == "dp_rough"; }
  double mu_normal() const { return mu_n.value_or(mu); }
  double mu_tangential() const { return mu_t.value_or(mu); }
  /// Friction acts on the normal and tangential parts with different coefficients.
  bool friction_split() const { return mu_normal() != mu_tangential(); }
  // Derived sizes (valid after resolve_and_validate).
  double sigma_small() const { return 2.0 / (1.0 + size_ratio); }
  double sigma_large() const { return size_ratio * sigma_small(); }
};

}  // namespace beverloo
