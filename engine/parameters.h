#pragma once
/// \file parameters.h
/// \brief The one table of job parameters: every field of a job file described once.
///
/// Each row gives the JSON path, the type, the unit, the default, the valid range, a one-line
/// doc, the models it applies to, whether a sweep may vary it, whether it enters the job key,
/// and how `query` users see it in SQL. Everything else is derived from this table:
///  - SimConfig::from_json / to_json / resolve_and_validate (engine/config.cpp) read, check and
///    write every row (only rules that relate two fields stay written out there);
///  - the sweepable axes of the sweep language (orchestrator/sweep);
///  - the typed SQL columns of the jobs table: generated columns over the stored job JSON (the
///    seed excepted), added by the store when it opens a campaign (no migration to write);
///  - the parameter tables of docs/job-file.md (`beverloo params --markdown`, checked by a test);
///  - the parameter list of schema/sweep.schema.json (checked by a test).
/// Adding a physics parameter = one row here, the physics code that uses it, its test.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace beverloo {

struct SimConfig;

enum class ParamType {
  Real,          ///< a finite number
  Integer,       ///< an integer (int)
  Integer64,     ///< an integer (int64)
  Boolean,
  Text,
  OptionalReal,  ///< a finite number, or absent (then a documented fallback applies)
  RealOrAuto,    ///< a number or "auto" (dt)
  Seed,          ///< a non-negative 64-bit integer, or absent (derived from the parameters)
};

/// Which models a parameter applies to; given for another model it is an error.
enum class ParamModels { All, Sp, Dp, DpSmooth };

/// Accessors into SimConfig for the row's type (exactly one is set).
struct ParamAccess {
  double& (*real)(SimConfig&) = nullptr;
  int& (*integer)(SimConfig&) = nullptr;
  std::int64_t& (*integer64)(SimConfig&) = nullptr;
  bool& (*boolean)(SimConfig&) = nullptr;
  std::string& (*text)(SimConfig&) = nullptr;
  std::optional<double>& (*optional_real)(SimConfig&) = nullptr;
  std::optional<std::uint64_t>& (*seed)(SimConfig&) = nullptr;
};

struct ParamSpec {
  std::string_view path;          ///< JSON path in a job file: "E_sp", "dp.K_l", "run.t_max"
  ParamType type;
  std::string_view unit;          ///< "-" for pure numbers; code units are those of units.h
  std::string_view default_text;  ///< as documented ("100", "1600 (2D), 6400 (3D)", "= mu")
  std::string_view doc;           ///< one line
  ParamAccess access;
  // valid range (NaN: no bound on that side); Integer types use the same bounds
  double lo = std::numeric_limits<double>::quiet_NaN();
  double hi = std::numeric_limits<double>::quiet_NaN();
  bool lo_open = false;  ///< true: lo itself is refused
  bool hi_open = false;
  ParamModels models = ParamModels::All;
  bool required = false;         ///< must be given (no default)
  bool sweepable = true;         ///< a sweep may vary it
  bool in_key = true;            ///< enters the job key (false: cannot change a finished result)
  bool in_seed = true;           ///< enters the derived seed (false: cannot change the trajectory)
  /// Decides only when a run stops (t_max, target_rel_err, stop_unreachable, min_time): two jobs
  /// that differ only in such fields follow one trajectory, and the one that stops later may
  /// continue the other's final checkpoint (SimConfig::trajectory_json, HopperRun::prepare).
  bool stop_rule = false;
  /// Added after engine 0.2.0: the canonical job carries it only when it is not at its
  /// default, so that every job key made before it existed stays valid.
  bool omit_at_default = false;
  std::string_view sql_column;   ///< typed column of the jobs table and the runs view ("": none)
  /// for omit_at_default rows with a column: the SQL expression of the default (over other
  /// columns of jobs, e.g. "mu"), used when the job JSON does not carry the field
  std::string_view sql_default;
  std::string_view allowed;      ///< Text: the allowed values, comma-separated ("" any)

  bool has_lo() const { return lo == lo; }
  bool has_hi() const { return hi == hi; }
  /// "must be > 0", "must be in [3, 256]", ... ("" if unbounded)
  std::string rule_text() const;
  /// SQL type of the column: REAL, INTEGER or TEXT.
  std::string_view sql_type() const;
};

/// Every job parameter, in the order of docs/job-file.md.
const std::vector<ParamSpec>& job_parameters();
/// Whether a row applies to a model ("sp", "dp_smooth", "dp_rough"): given for another model it
/// is an error, and the canonical job leaves it out.
bool parameter_applies(ParamModels m, const std::string& model);
/// The row of a path, or nullptr.
const ParamSpec* find_parameter(std::string_view path);

/// Derived quantities, defined once (docs/sweeps.md).
namespace derived {
/// Mass of a particle of diameter sigma_avg (pi/4 in 2D, pi/6 in 3D): the mass that turns a
/// drag rate into a drag coefficient for lambda (as the authors' lambda axis does).
double mean_particle_mass(int dimension);
/// The drag coefficient of that particle: zeta + drag_rate * mean_particle_mass.
double drag_coefficient(const SimConfig& c);
/// The tangential kinetic friction coefficient (mu_t, or mu when it is not split).
double friction_coefficient(const SimConfig& c);
/// lambda = drag_coefficient / friction_coefficient: +inf when there is drag and no friction,
/// nullopt when there is neither (undefined; stored as NULL).
std::optional<double> lambda(const SimConfig& c);
/// The dissipation scale sqrt(zeta_eff mu_t) when both are > 0, else the nonzero one (or 0).
double dissipation_scale(const SimConfig& c);

/// The sweeps' lambda axis at a dissipation scale s (docs/sweeps.md), defined here once: the
/// text's reference values are zeta = s / sqrt 10 and mu = 10 s sqrt 10 (physics.md), so a
/// finite lambda > 0 is zeta = s / sqrt 10, mu = zeta / lambda; lambda = 0 is zeta = 0,
/// mu = 10 s sqrt 10; lambda = +inf is zeta = s / sqrt 10, mu = 0.
struct ZetaMu {
  double zeta, mu;
};
ZetaMu on_lambda_axis(double lambda, double scale);
/// The scale s of a job on that axis from its zeta (> 0), or from its mu when zeta = 0 (lambda = 0).
double axis_scale_of_zeta(double zeta);
double axis_scale_of_friction_limit(double mu);
}  // namespace derived

/// The parameter tables of docs/job-file.md, generated from the table (Markdown).
std::string parameters_markdown();

}  // namespace beverloo
