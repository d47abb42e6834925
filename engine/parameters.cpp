#include "parameters.h"

#include <cmath>
#include <sstream>

#include "config.h"
#include "forces/contact_laws.h"
#include "units.h"

// Rows are designated initialisers that name only what differs from ParamSpec's member
// defaults; -Wextra would warn about every member left to its default.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace beverloo {
namespace {

// One accessor per row; captureless lambdas turn into the function pointers of ParamAccess.
#define REAL(member) ParamAccess{.real = [](SimConfig& c) -> double& { return c.member; }}
#define INT(member) ParamAccess{.integer = [](SimConfig& c) -> int& { return c.member; }}
#define INT64(member) ParamAccess{.integer64 = [](SimConfig& c) -> std::int64_t& { return c.member; }}
#define BOOL(member) ParamAccess{.boolean = [](SimConfig& c) -> bool& { return c.member; }}
#define TEXT(member) ParamAccess{.text = [](SimConfig& c) -> std::string& { return c.member; }}
#define OPT_REAL(member) ParamAccess{.optional_real = [](SimConfig& c) -> std::optional<double>& { return c.member; }}

std::vector<ParamSpec> build_table() {
  using T = ParamType;
  using M = ParamModels;
  return {
      // --- model and system ------------------------------------------------------------
      {.path = "model", .type = T::Text, .unit = "-", .default_text = "\"sp\"",
       .doc = "\"sp\" soft particles (2D, 3D); \"dp_smooth\" deformable polygons with circulo-line edges, \"dp_rough\" with vertex disks (2D)",
       .access = TEXT(model), .sql_column = "model", .allowed = "sp,dp_smooth,dp_rough"},
      {.path = "dimension", .type = T::Integer, .unit = "-", .default_text = "2", .doc = "2 or 3 (DP: 2 only)",
       .access = INT(dimension), .lo = 2, .hi = 3, .sql_column = "dimension"},
      {.path = "N", .type = T::Integer, .unit = "-", .default_text = "1600 (2D), 6400 (3D)",
       .doc = "number of particles, half small and half large", .access = INT(N), .lo = 2, .hi = 5e7,
       .sql_column = "N"},
      {.path = "size_ratio", .type = T::Real, .unit = "-", .default_text = "1.4", .doc = "sigma_l / sigma_s",
       .access = REAL(size_ratio), .lo = 1, .hi = 10, .sql_column = "size_ratio"},
      {.path = "W", .type = T::Real, .unit = "sigma_avg", .default_text = "50 (2D), 25 (3D)",
       .doc = "container width (2D) or cylinder diameter (3D)", .access = REAL(W), .lo = 0, .lo_open = true,
       .sql_column = "W_container"},
      {.path = "w", .type = T::Real, .unit = "sigma_avg", .default_text = "required",
       .doc = "orifice width (2D) or diameter (3D), 0 < w < W", .access = REAL(w), .lo = 0, .lo_open = true,
       .required = true, .sql_column = "w"},
      {.path = "theta_w_deg", .type = T::Real, .unit = "deg", .default_text = "90",
       .doc = "funnel angle from gravity, both sides (90 = flat bottom; 3D: 90 only); shorthand for the two below",
       .lo = 0, .hi = 90, .in_key = false},
      {.path = "theta_w_left_deg", .type = T::Real, .unit = "deg", .default_text = "90",
       .doc = "funnel angle from gravity, left wall (2D; 0 = vertical: the orifice sits in the container's left corner)",
       .access = REAL(theta_w_left_deg), .lo = 0, .hi = 90, .sql_column = "theta_w_left_deg"},
      {.path = "theta_w_right_deg", .type = T::Real, .unit = "deg", .default_text = "90",
       .doc = "funnel angle from gravity, right wall (2D; 0 = vertical: the orifice sits in the container's right corner)",
       .access = REAL(theta_w_right_deg), .lo = 0, .hi = 90, .sql_column = "theta_w_right_deg"},
      // --- interactions ----------------------------------------------------------------
      {.path = "E_sp", .type = T::Real, .unit = "g rho sigma_avg^(d+1)", .default_text = "100",
       .doc = "pair stiffness, U = (E_sp/2)(1 - r/sigma_mn)^2", .access = REAL(E_sp), .lo = 0, .lo_open = true,
       .models = M::Sp, .sql_column = "E_sp"},
      {.path = "sp_contact_law", .type = T::Text, .unit = "-", .default_text = "\"energy\"",
       .doc = normal_law_docs(),
       .access = TEXT(sp_contact_law), .models = M::Sp, .omit_at_default = true, .sql_column = "sp_contact_law",
       .sql_default = "CASE WHEN model = 'sp' THEN 'energy' END", .allowed = normal_law_names()},
      {.path = "E_w", .type = T::Real, .unit = "g rho sigma_avg^(d+1)", .default_text = "1e4",
       .doc = "wall stiffness, U = (E_w/2)(1 - 2 d/sigma)^2 (DP: per vertex, d against delta)", .access = REAL(E_w),
       .lo = 0, .lo_open = true, .sql_column = "E_w"},
      {.path = "zeta", .type = T::Real, .unit = "rho sigma_avg^(d-1) g t0", .default_text = "required",
       .doc = "viscous drag coefficient, F = -zeta v per particle (DP: zeta/n_v per vertex); 0: no such drag",
       .access = REAL(zeta), .lo = 0, .required = true, .sql_column = "zeta"},
      {.path = "drag_rate", .type = T::Real, .unit = "1/t0", .default_text = "0",
       .doc = "drag as a rate times the mass, F = -drag_rate M v (DP: each vertex's mass), added to zeta's; the authors' code's form",
       .access = REAL(drag_rate), .lo = 0, .omit_at_default = true, .sql_column = "drag_rate", .sql_default = "0"},
      {.path = "mu", .type = T::Real, .unit = "rho sigma_avg^(d-1) g t0", .default_text = "required",
       .doc = "kinetic friction between overlapping particles, F = -mu (v_m - v_n); 0: drag only",
       .access = REAL(mu), .lo = 0, .required = true, .sql_column = "mu"},
      {.path = "mu_n", .type = T::OptionalReal, .unit = "rho sigma_avg^(d-1) g t0", .default_text = "= mu",
       .doc = "kinetic friction on the normal part of the relative velocity (the authors' code: 0)",
       .access = OPT_REAL(mu_n), .lo = 0, .omit_at_default = true, .sql_column = "mu_n", .sql_default = "mu"},
      {.path = "mu_t", .type = T::OptionalReal, .unit = "rho sigma_avg^(d-1) g t0", .default_text = "= mu",
       .doc = "kinetic friction on the tangential part of the relative velocity", .access = OPT_REAL(mu_t),
       .lo = 0, .omit_at_default = true, .sql_column = "mu_t", .sql_default = "mu"},
      {.path = "gravity", .type = T::Real, .unit = "g", .default_text = "1", .doc = "gravitational acceleration",
       .access = REAL(gravity), .lo = 0, .sql_column = "gravity"},
      // --- deformable particles ----------------------------------------------------------
      {.path = "dp.n_v", .type = T::Integer, .unit = "-", .default_text = "16", .doc = "vertices per polygon",
       .access = INT(dp.n_v), .lo = 3, .hi = 256, .models = M::Dp, .sql_column = "n_v"},
      {.path = "dp.K_a", .type = T::Real, .unit = "g rho sigma_avg^3", .default_text = "1e4",
       .doc = "area term (K_a/2)(a - a0)^2", .access = REAL(dp.K_a), .lo = 0, .lo_open = true, .models = M::Dp,
       .sql_column = "K_a"},
      {.path = "dp.K_l", .type = T::Real, .unit = "g rho sigma_avg^3", .default_text = "10",
       .doc = "segment term (K_l n_v/2) sum (l_i - l0)^2", .access = REAL(dp.K_l), .lo = 0, .lo_open = true,
       .models = M::Dp, .sql_column = "K_l"},
      {.path = "dp.K_b", .type = T::Real, .unit = "g rho sigma_avg^3", .default_text = "0.1",
       .doc = "bending term (K_b/(2 n_v)) sum |lhat_i - lhat_i+1|^2 / l0^2 (> 1e2: rigid)", .access = REAL(dp.K_b),
       .lo = 0, .models = M::Dp, .sql_column = "K_b"},
      {.path = "dp.E_c", .type = T::Real, .unit = "g rho sigma_avg^3", .default_text = "1e4",
       .doc = "contact stiffness, vertex disks (rough) or vertex-edge (smooth)", .access = REAL(dp.E_c), .lo = 0,
       .lo_open = true, .models = M::Dp, .sql_column = "E_c"},
      {.path = "dp.contact_width", .type = T::Real, .unit = "l0", .default_text = "0.1",
       .doc = "smooth DP: width delta of an edge's circulo-line (the authors' code: 0.2)",
       .access = REAL(dp.contact_width), .lo = 0, .hi = 1, .lo_open = true, .models = M::DpSmooth,
       .omit_at_default = true, .sql_column = "contact_width",
       .sql_default = "CASE WHEN model = 'dp_smooth' THEN 0.1 END"},
      {.path = "dp.K_l_large", .type = T::OptionalReal, .unit = "g rho sigma_avg^3", .default_text = "= dp.K_l",
       .doc = "segment stiffness of the large species (the authors' code: 1.40 x the small's)",
       .access = OPT_REAL(dp.K_l_large), .lo = 0, .lo_open = true, .models = M::Dp, .omit_at_default = true,
       .sql_column = "K_l_large", .sql_default = "K_l"},
      {.path = "dp.K_a_large", .type = T::OptionalReal, .unit = "g rho sigma_avg^3", .default_text = "= dp.K_a",
       .doc = "area stiffness of the large species (the authors' code: ka/a0 per species, 0.51 x the small's)",
       .access = OPT_REAL(dp.K_a_large), .lo = 0, .lo_open = true, .models = M::Dp, .omit_at_default = true,
       .sql_column = "K_a_large", .sql_default = "K_a"},
      {.path = "dp.E_c_vertex", .type = T::OptionalReal, .unit = "g rho sigma_avg^3", .default_text = "= dp.E_c",
       .doc = "smooth DP: contact stiffness of a vertex at a polygon's corner (vertex-vertex; the authors' code: E_c/2)",
       .access = OPT_REAL(dp.E_c_vertex), .lo = 0, .lo_open = true, .models = M::DpSmooth, .omit_at_default = true,
       .sql_column = "E_c_vertex", .sql_default = "CASE WHEN model = 'dp_smooth' THEN E_c END"},
      {.path = "dp.wall_width", .type = T::OptionalReal, .unit = "l0", .default_text = "= contact diameter",
       .doc = "diameter of a vertex against walls and orifice corners (unset: dp.contact_width smooth, 1 rough; the authors' code: 1)",
       .access = OPT_REAL(dp.wall_width), .lo = 0, .hi = 4, .lo_open = true, .models = M::Dp, .omit_at_default = true,
       .sql_column = "wall_width",
       .sql_default = "CASE WHEN model = 'dp_smooth' THEN contact_width WHEN model = 'dp_rough' THEN 1 END"},
      {.path = "dp.wall_thickness", .type = T::Real, .unit = "l0 (small)", .default_text = "0",
       .doc = "thickness of the funnel walls, their orifice ends rounded, the side walls then half-spaces (0: walls are lines; the authors' code: a floor 1 l0 thick, its lip a bead 1 l0 wide)",
       .access = REAL(dp.wall_thickness), .lo = 0, .hi = 4, .models = M::Dp, .omit_at_default = true,
       .sql_column = "wall_thickness", .sql_default = "CASE WHEN model LIKE 'dp_%' THEN 0 END"},
      // --- numerics ----------------------------------------------------------------------
      {.path = "dt", .type = T::RealOrAuto, .unit = "t0", .default_text = "\"auto\"",
       .doc = "time step: a number, or \"auto\" = min(1e-3, T_min/15, tau_min/5) from the stiffest term",
       .access = OPT_REAL(dt), .lo = 0, .lo_open = true},
      {.path = "skin", .type = T::Real, .unit = "sigma_avg", .default_text = "0.3 (SP), 0.1 (DP)",
       .doc = "Verlet-list skin (speed only; results do not depend on it)", .access = REAL(skin), .lo = 0, .hi = 2,
       .lo_open = true, .sweepable = true, .in_key = false, .in_seed = false},
      {.path = "max_overlap", .type = T::Real, .unit = "-", .default_text = "0.99",
       .doc = "a relative pair overlap 1 - r/sigma_mn above this stops the run as unstable",
       .access = REAL(max_overlap), .lo = 0, .hi = 1, .lo_open = true, .hi_open = true, .in_key = false,
       .in_seed = false},
      // --- protocol ----------------------------------------------------------------------
      {.path = "initial_packing_fraction", .type = T::Real, .unit = "-", .default_text = "0.5",
       .doc = "density of the random placement above the funnel", .access = REAL(initial_packing_fraction),
       .lo = 0, .hi = 0.6, .lo_open = true},
      {.path = "reinject", .type = T::Boolean, .unit = "-", .default_text = "true",
       .doc = "false: draining hopper, no reinjection", .access = BOOL(reinject)},
      {.path = "seed", .type = T::Seed, .unit = "-", .default_text = "derived",
       .doc = "RNG seed; default: a hash of the canonical job without run controls and seed",
       .access = ParamAccess{.seed = [](SimConfig& c) -> std::optional<std::uint64_t>& { return c.seed; }},
       .in_seed = false, .sql_column = "seed"},
      {.path = "replica", .type = T::Integer, .unit = "-", .default_text = "0",
       .doc = "changes the derived seed and nothing else", .access = INT(replica), .lo = 0, .sql_column = "replica"},
      // --- FIRE (Bitzek et al. 2006) -----------------------------------------------------
      {.path = "fire.alpha0", .type = T::Real, .unit = "-", .default_text = "0.1", .doc = "initial mixing",
       .access = REAL(fire.alpha0), .lo = 0, .hi = 1, .lo_open = true, .hi_open = true, .sweepable = false},
      {.path = "fire.f_inc", .type = T::Real, .unit = "-", .default_text = "1.1", .doc = "time-step growth",
       .access = REAL(fire.f_inc), .lo = 1, .lo_open = true, .sweepable = false},
      {.path = "fire.f_dec", .type = T::Real, .unit = "-", .default_text = "0.5", .doc = "time-step cut",
       .access = REAL(fire.f_dec), .lo = 0, .hi = 1, .lo_open = true, .hi_open = true, .sweepable = false},
      {.path = "fire.f_alpha", .type = T::Real, .unit = "-", .default_text = "0.99", .doc = "mixing decay",
       .access = REAL(fire.f_alpha), .lo = 0, .hi = 1, .lo_open = true, .hi_open = true, .sweepable = false},
      {.path = "fire.n_min", .type = T::Integer, .unit = "-", .default_text = "5",
       .doc = "steps downhill before the time step grows", .access = INT(fire.n_min), .lo = 0, .sweepable = false},
      {.path = "fire.dt_max_factor", .type = T::Real, .unit = "-", .default_text = "10", .doc = "dt_max = this * dt",
       .access = REAL(fire.dt_max_factor), .lo = 1, .sweepable = false},
      {.path = "fire.force_tol", .type = T::Real, .unit = "code force", .default_text = "1e-6",
       .doc = "stop when max |F| falls below this", .access = REAL(fire.force_tol), .lo = 0, .lo_open = true,
       .sweepable = false},
      {.path = "fire.max_iter", .type = T::Integer64, .unit = "-", .default_text = "2e6", .doc = "iteration limit",
       .access = INT64(fire.max_iter), .lo = 0, .lo_open = true, .sweepable = false},
      {.path = "fire.max_pair_stiffness", .type = T::Real, .unit = "g rho sigma_avg^(d+1)", .default_text = "100",
       .doc = "FIRE uses min(E_sp, this): stiff random overlaps would push particles through the walls",
       .access = REAL(fire.max_pair_stiffness), .lo = 0, .lo_open = true, .sweepable = false},
      // --- run controls (not in the derived seed) ------------------------------------------
      {.path = "run.t_max", .type = T::Real, .unit = "t0", .default_text = "2000",
       .doc = "flowing time limit after gravity is switched on", .access = REAL(run.t_max), .lo = 0,
       .lo_open = true, .in_seed = false, .stop_rule = true, .sql_column = "t_max"},
      {.path = "run.target_rel_err", .type = T::Real, .unit = "-", .default_text = "0.02",
       .doc = "stop when SE(Q)/Q is at most this", .access = REAL(run.target_rel_err), .lo = 0, .hi = 1,
       .lo_open = true, .hi_open = true, .in_seed = false, .stop_rule = true, .sql_column = "target_rel_err"},
      {.path = "run.t_clog", .type = T::Real, .unit = "t0", .default_text = "100", .doc = "no exit for this long: clogged",
       .access = REAL(run.t_clog), .lo = 0, .lo_open = true, .in_seed = false},
      {.path = "run.stop_unreachable", .type = T::Boolean, .unit = "-", .default_text = "false",
       .doc = "true: stop once the error's fall (1/sqrt of the window) predicts that run.t_max cannot reach run.target_rel_err "
              "(status unreachable; Q with its error)",
       .access = BOOL(run.stop_unreachable), .in_seed = false, .stop_rule = true, .omit_at_default = true,
       .sql_column = "stop_unreachable", .sql_default = "0"},
      {.path = "run.min_time", .type = T::Real, .unit = "t0", .default_text = "0",
       .doc = "no stopping rule but the clog's ends the run before this flowing time (0: none; above run.t_max it is "
              "the time limit): more flow time for a finished job, which the job with the larger run.min_time continues "
              "from its final checkpoint",
       .access = REAL(run.min_time), .lo = 0, .in_seed = false, .stop_rule = true, .omit_at_default = true,
       .sql_column = "min_time", .sql_default = "0"},
      {.path = "run.min_transient", .type = T::Real, .unit = "t0", .default_text = "20",
       .doc = "the transient cut is at least this long", .access = REAL(run.min_transient), .lo = 0,
       .in_seed = false},
      {.path = "run.min_window", .type = T::Real, .unit = "t0", .default_text = "100",
       .doc = "the measurement window is at least this long before the error rule may stop the run",
       .access = REAL(run.min_window), .lo = 0, .lo_open = true, .in_seed = false},
      {.path = "run.check_interval", .type = T::Real, .unit = "t0", .default_text = "10",
       .doc = "how often the stopping rule is evaluated", .access = REAL(run.check_interval), .lo = 0,
       .lo_open = true, .in_seed = false},
      {.path = "run.rate_bin", .type = T::Real, .unit = "t0", .default_text = "1",
       .doc = "bin width of the exit-rate series (at most run.min_window / 8; a bin shorter than a time step counts no exits)",
       .access = REAL(run.rate_bin), .lo = 1e-4, .in_seed = false},
      {.path = "run.checkpoint_interval", .type = T::Real, .unit = "t0", .default_text = "100",
       .doc = "simulated time between checkpoints (0: none; also every 10 min of wall time)",
       .access = REAL(run.checkpoint_interval), .lo = 0, .sweepable = false, .in_key = false, .in_seed = false},
      {.path = "run.trajectory_every_steps", .type = T::Integer64, .unit = "steps", .default_text = "0",
       .doc = "H5MD frame every K steps (0: no trajectory)", .access = INT64(run.trajectory_every_steps), .lo = 0,
       .sweepable = false, .in_key = false, .in_seed = false},
      // --- reinjection -------------------------------------------------------------------
      {.path = "reinjection.drop_depth_diameters", .type = T::Real, .unit = "own diameters", .default_text = "2",
       .doc = "reinject once this far below the orifice", .access = REAL(reinjection.drop_depth_diameters), .lo = 1,
       .sweepable = false},
      {.path = "reinjection.top_band", .type = T::Real, .unit = "sigma_avg", .default_text = "3",
       .doc = "touch one of the pile particles within this of the pile's highest", .access = REAL(reinjection.top_band),
       .lo = 0, .lo_open = true, .sweepable = false},
      {.path = "reinjection.max_attempts", .type = T::Integer, .unit = "-", .default_text = "500",
       .doc = "random placements tried before the fallback", .access = INT(reinjection.max_attempts), .lo = 1,
       .sweepable = false},
      {.path = "reinjection.rule", .type = T::Text, .unit = "-", .default_text = "\"pile\"",
       .doc = "\"pile\": touching a topmost pile particle, with its velocity (the text); \"lanes\": above the top of one of fixed lanes 2 small diameters apart, in turn, with the lane's velocity and a sideways kick (the authors' code; 2D)",
       .access = TEXT(reinjection.rule), .omit_at_default = true, .sql_column = "reinjection_rule",
       .sql_default = "'pile'", .allowed = "pile,lanes"},
      // --- draining hopper (reinject = false) -------------------------------------------
      {.path = "drain.stop_below", .type = T::Integer, .unit = "particles", .default_text = "0",
       .doc = "draining hopper: the run ends once at most this many particles remain in it (0: when all have left)",
       .access = INT(drain.stop_below), .lo = 0, .in_seed = false, .omit_at_default = true,
       .sql_column = "drain_stop_below", .sql_default = "0"},
      {.path = "drain.fit_skip", .type = T::Integer, .unit = "exits", .default_text = "100",
       .doc = "draining hopper: the fit of dN/dt = -c0 sqrt(N) leaves out the first n exits and those made with fewer than n left",
       .access = INT(drain.fit_skip), .lo = 0, .in_seed = false, .omit_at_default = true,
       .sql_column = "drain_fit_skip", .sql_default = "100"},
      {.path = "drain.block_exits", .type = T::Integer, .unit = "exits", .default_text = "10",
       .doc = "draining hopper: exits per rate block of that fit", .access = INT(drain.block_exits), .lo = 2,
       .sweepable = false, .in_seed = false, .omit_at_default = true, .sql_column = "drain_block_exits",
       .sql_default = "10"},
      // --- observables -------------------------------------------------------------------
      {.path = "observables.sample_interval", .type = T::Real, .unit = "t0", .default_text = "0.1",
       .doc = "time between samples of profile, density and forces", .access = REAL(observables.sample_interval),
       .lo = 0, .lo_open = true, .sweepable = false},
      {.path = "observables.block_length", .type = T::Real, .unit = "t0", .default_text = "5",
       .doc = "time per accumulation block (at least sample_interval)", .access = REAL(observables.block_length),
       .lo = 0, .lo_open = true, .sweepable = false},
      {.path = "observables.profile_dh", .type = T::Real, .unit = "sigma_avg", .default_text = "0.25",
       .doc = "height spacing of v_g(h)", .access = REAL(observables.profile_dh), .lo = 0, .lo_open = true,
       .sweepable = false},
      {.path = "observables.profile_h_max", .type = T::Real, .unit = "sigma_avg", .default_text = "30",
       .doc = "largest height of v_g(h) above the orifice (above profile_dh)", .access = REAL(observables.profile_h_max),
       .lo = 0, .lo_open = true, .sweepable = false},
      {.path = "observables.kernel_width", .type = T::Real, .unit = "sigma_avg", .default_text = "1",
       .doc = "Gaussian coarse-graining width", .access = REAL(observables.kernel_width), .lo = 0, .lo_open = true,
       .sweepable = false},
  };
}

std::string bound(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

std::string ParamSpec::rule_text() const {
  std::string r;
  if (has_lo() && has_hi())
    r = "must be in " + std::string(lo_open ? "(" : "[") + bound(lo) + ", " + bound(hi) + (hi_open ? ")" : "]");
  else if (has_lo())
    r = std::string("must be ") + (lo_open ? "> " : ">= ") + bound(lo);
  else if (has_hi())
    r = std::string("must be ") + (hi_open ? "< " : "<= ") + bound(hi);
  if (!r.empty() && unit == "deg") r += " degrees";
  return r;
}

std::string_view ParamSpec::sql_type() const {
  switch (type) {
    case ParamType::Integer:
    case ParamType::Integer64:
    case ParamType::Boolean:
    case ParamType::Seed:
      return "INTEGER";
    case ParamType::Text:
      return "TEXT";
    default:
      return "REAL";
  }
}

const std::vector<ParamSpec>& job_parameters() {
  static const std::vector<ParamSpec> table = build_table();
  return table;
}

bool parameter_applies(ParamModels m, const std::string& model) {
  switch (m) {
    case ParamModels::All: return true;
    case ParamModels::Sp: return model == "sp";
    case ParamModels::Dp: return model == "dp_smooth" || model == "dp_rough";
    case ParamModels::DpSmooth: return model == "dp_smooth";
  }
  return true;
}

const ParamSpec* find_parameter(std::string_view path) {
  for (const ParamSpec& p : job_parameters())
    if (p.path == path) return &p;
  return nullptr;
}

namespace derived {
double mean_particle_mass(int dimension) {
  return dimension == 2 ? units::pi / 4 : units::pi / 6;  // rho sigma_avg^2 pi/4, rho sigma_avg^3 pi/6
}
double drag_coefficient(const SimConfig& c) { return c.zeta + c.drag_rate * mean_particle_mass(c.dimension); }
double friction_coefficient(const SimConfig& c) { return c.mu_tangential(); }
std::optional<double> lambda(const SimConfig& c) {
  const double z = drag_coefficient(c), m = friction_coefficient(c);
  if (m > 0) return z / m;
  if (z > 0) return INFINITY;
  return std::nullopt;
}
double dissipation_scale(const SimConfig& c) {
  const double z = drag_coefficient(c), m = friction_coefficient(c);
  if (z > 0 && m > 0) return std::sqrt(z * m);
  return z + m;
}
ZetaMu on_lambda_axis(double lambda, double scale) {
  const double zeta_ref = scale / std::sqrt(10.0);
  if (lambda == 0) return {0.0, scale * 10 * std::sqrt(10.0)};
  if (std::isinf(lambda)) return {zeta_ref, 0.0};
  return {zeta_ref, zeta_ref / lambda};
}
double axis_scale_of_zeta(double zeta) { return zeta * std::sqrt(10.0); }
double axis_scale_of_friction_limit(double mu) { return mu / (10 * std::sqrt(10.0)); }
}  // namespace derived

std::string parameters_markdown() {
  std::ostringstream md;
  std::string group = "-";
  for (const ParamSpec& p : job_parameters()) {
    const auto dot = p.path.find('.');
    const std::string g = dot == std::string_view::npos ? "" : std::string(p.path.substr(0, dot));
    if (g != group) {
      if (group != "-") md << "\n";
      md << (g.empty() ? "Top level" : "`" + g + "`") << ":\n\n"
         << "| field | unit | default | valid | sweep | key | SQL column | meaning |\n"
         << "|---|---|---|---|---|---|---|---|\n";
      group = g;
    }
    std::string valid = p.rule_text();
    if (valid.rfind("must be ", 0) == 0) valid = valid.substr(8);
    if (!p.allowed.empty()) valid = "one of " + std::string(p.allowed);
    if (p.type == ParamType::Boolean) valid = "true, false";
    std::string models;
    if (p.models == ParamModels::Sp) models = " (SP only)";
    if (p.models == ParamModels::Dp) models = " (DP only)";
    if (p.models == ParamModels::DpSmooth) models = " (dp_smooth only)";
    md << "| `" << p.path << "` | " << p.unit << " | " << p.default_text << " | " << (valid.empty() ? "any" : valid)
       << " | " << (p.sweepable ? "yes" : "no") << " | " << (p.in_key ? "yes" : "no") << " | ";
    if (!p.sql_column.empty()) md << "`" << p.sql_column << "`";
    md << " | " << p.doc << models << " |\n";
  }
  return md.str();
}

}  // namespace beverloo
