#include "config.h"

#include <cmath>
#include <set>

#include "rng.h"

namespace beverloo {
namespace {

using nlohmann::json;

/// Reads fields of one JSON object, remembering which were used so that unknown ones are errors.
class FieldReader {
 public:
  FieldReader(const json& obj, std::string path) : obj_(obj), path_(std::move(path)) {
    if (!obj_.is_object()) throw ConfigError(path_.empty() ? "(top level)" : path_, "must be a JSON object");
  }
  std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) const { return obj_.contains(key); }

  void number(const std::string& key, double& out) {
    if (!take(key)) return;
    const json& v = obj_.at(key);
    if (!v.is_number()) throw ConfigError(field(key), "must be a number, got " + v.dump());
    out = v.get<double>();
    if (!std::isfinite(out)) throw ConfigError(field(key), "must be finite");
  }
  template <typename Int>
  void integer(const std::string& key, Int& out) {
    if (!take(key)) return;
    const json& v = obj_.at(key);
    if (v.is_number_integer() || v.is_number_unsigned()) {
      out = v.get<Int>();
      return;
    }
    if (v.is_number_float()) {
      const double d = v.get<double>();
      if (std::floor(d) == d && std::fabs(d) < 9e15) {
        out = static_cast<Int>(d);
        return;
      }
    }
    throw ConfigError(field(key), "must be an integer, got " + v.dump());
  }
  void boolean(const std::string& key, bool& out) {
    if (!take(key)) return;
    const json& v = obj_.at(key);
    if (!v.is_boolean()) throw ConfigError(field(key), "must be true or false, got " + v.dump());
    out = v.get<bool>();
  }
  void string(const std::string& key, std::string& out) {
    if (!take(key)) return;
    const json& v = obj_.at(key);
    if (!v.is_string()) throw ConfigError(field(key), "must be a string, got " + v.dump());
    out = v.get<std::string>();
  }
  const json* object(const std::string& key) {
    if (!take(key)) return nullptr;
    return &obj_.at(key);
  }
  const json* raw(const std::string& key) { return take(key) ? &obj_.at(key) : nullptr; }
  void reject_unknown() const {
    for (auto it = obj_.begin(); it != obj_.end(); ++it)
      if (!used_.count(it.key())) throw ConfigError(field(it.key()), "unknown field");
  }

 private:
  bool take(const std::string& key) {
    if (!obj_.contains(key)) return false;
    used_.insert(key);
    return true;
  }
  const json& obj_;
  std::string path_;
  std::set<std::string> used_;
};

void require(bool ok, const std::string& field, const std::string& reason) {
  if (!ok) throw ConfigError(field, reason);
}
std::string num(double x) { return json(x).dump(); }

}  // namespace

SimConfig SimConfig::from_json(const json& j) {
  SimConfig c;
  FieldReader r(j, "");
  r.string("model", c.model);
  r.integer("dimension", c.dimension);
  r.integer("N", c.N);
  r.number("size_ratio", c.size_ratio);
  r.number("W", c.W);
  r.number("w", c.w);
  if (r.has("theta_w_deg") && (r.has("theta_w_left_deg") || r.has("theta_w_right_deg")))
    throw ConfigError("theta_w_deg", "give either theta_w_deg or theta_w_left_deg/theta_w_right_deg, not both");
  double theta = 90.0;
  if (r.has("theta_w_deg")) {
    r.number("theta_w_deg", theta);
    c.theta_w_left_deg = c.theta_w_right_deg = theta;
  }
  r.number("theta_w_left_deg", c.theta_w_left_deg);
  r.number("theta_w_right_deg", c.theta_w_right_deg);
  if (r.has("E_sp") && (c.model == "dp_smooth" || c.model == "dp_rough"))
    throw ConfigError("E_sp", "applies to model \"sp\" only; the DP contact stiffness is dp.E_c");
  r.number("E_sp", c.E_sp);
  r.number("E_w", c.E_w);
  if (const json* d = r.object("dp")) {
    if (!c.is_dp()) throw ConfigError("dp", "applies to the models \"dp_smooth\" and \"dp_rough\" only, not \"" + c.model + "\"");
    FieldReader dr(*d, "dp");
    dr.integer("n_v", c.dp.n_v);
    dr.number("K_a", c.dp.K_a);
    dr.number("K_l", c.dp.K_l);
    dr.number("K_b", c.dp.K_b);
    dr.number("E_c", c.dp.E_c);
    dr.reject_unknown();
  }
  r.number("zeta", c.zeta);
  r.number("mu", c.mu);
  r.number("gravity", c.gravity);
  if (const json* dt = r.raw("dt")) {
    if (dt->is_string()) {
      if (dt->get<std::string>() != "auto") throw ConfigError("dt", "must be a number or \"auto\", got " + dt->dump());
    } else if (dt->is_number()) {
      c.dt = dt->get<double>();
    } else {
      throw ConfigError("dt", "must be a number or \"auto\", got " + dt->dump());
    }
  }
  r.number("skin", c.skin);
  r.number("max_overlap", c.max_overlap);
  r.number("initial_packing_fraction", c.initial_packing_fraction);
  r.boolean("reinject", c.reinject);
  if (const json* s = r.raw("seed")) {
    if (!s->is_number_unsigned() && !(s->is_number_integer() && s->get<std::int64_t>() >= 0))
      throw ConfigError("seed", "must be a non-negative integer, got " + s->dump());
    c.seed = s->get<std::uint64_t>();
  }
  r.integer("replica", c.replica);
  if (const json* f = r.object("fire")) {
    FieldReader fr(*f, "fire");
    fr.number("alpha0", c.fire.alpha0);
    fr.number("f_inc", c.fire.f_inc);
    fr.number("f_dec", c.fire.f_dec);
    fr.number("f_alpha", c.fire.f_alpha);
    fr.integer("n_min", c.fire.n_min);
    fr.number("dt_max_factor", c.fire.dt_max_factor);
    fr.number("force_tol", c.fire.force_tol);
    fr.integer("max_iter", c.fire.max_iter);
    fr.number("max_pair_stiffness", c.fire.max_pair_stiffness);
    fr.reject_unknown();
  }
  if (const json* run = r.object("run")) {
    FieldReader rr(*run, "run");
    rr.number("t_max", c.run.t_max);
    rr.number("target_rel_err", c.run.target_rel_err);
    rr.number("t_clog", c.run.t_clog);
    rr.number("min_transient", c.run.min_transient);
    rr.number("min_window", c.run.min_window);
    rr.number("check_interval", c.run.check_interval);
    rr.number("rate_bin", c.run.rate_bin);
    rr.number("checkpoint_interval", c.run.checkpoint_interval);
    rr.integer("trajectory_every_steps", c.run.trajectory_every_steps);
    rr.reject_unknown();
  }
  if (const json* re = r.object("reinjection")) {
    FieldReader rr(*re, "reinjection");
    rr.number("drop_depth_diameters", c.reinjection.drop_depth_diameters);
    rr.number("top_band", c.reinjection.top_band);
    rr.integer("max_attempts", c.reinjection.max_attempts);
    rr.reject_unknown();
  }
  if (const json* ob = r.object("observables")) {
    FieldReader orr(*ob, "observables");
    orr.number("sample_interval", c.observables.sample_interval);
    orr.number("block_length", c.observables.block_length);
    orr.number("profile_dh", c.observables.profile_dh);
    orr.number("profile_h_max", c.observables.profile_h_max);
    orr.number("kernel_width", c.observables.kernel_width);
    orr.reject_unknown();
  }
  std::string comment;  // free text for people; not part of the job
  r.string("comment", comment);
  r.reject_unknown();
  c.resolve_and_validate();
  return c;
}

void SimConfig::resolve_and_validate() {
  require(model == "sp" || is_dp(), "model",
          "\"" + model + "\" is not a known model (known: \"sp\", \"dp_smooth\", \"dp_rough\")");
  require(dimension == 2 || dimension == 3, "dimension", "must be 2 or 3, got " + std::to_string(dimension));
  if (is_dp()) {
    require(dimension == 2, "dimension", "the DP models are 2D only (physics.md 4), got " + std::to_string(dimension));
    require(dp.n_v >= 3 && dp.n_v <= 256, "dp.n_v", "must be in [3, 256], got " + std::to_string(dp.n_v));
    require(dp.K_a > 0, "dp.K_a", "must be > 0, got " + num(dp.K_a));
    require(dp.K_l > 0, "dp.K_l", "must be > 0, got " + num(dp.K_l));
    require(dp.K_b >= 0, "dp.K_b", "must be >= 0, got " + num(dp.K_b));
    require(dp.E_c > 0, "dp.E_c", "must be > 0, got " + num(dp.E_c));
  }
  if (skin == 0) skin = is_dp() ? 0.1 : 0.3;
  if (N == 0) N = dimension == 2 ? 1600 : 6400;
  if (W == 0) W = dimension == 2 ? 50.0 : 25.0;
  require(N >= 2, "N", "must be at least 2, got " + std::to_string(N));
  require(N <= 50'000'000, "N", "must be at most 5e7, got " + std::to_string(N));
  require(size_ratio >= 1.0 && size_ratio <= 10.0, "size_ratio", "must be in [1, 10], got " + num(size_ratio));
  require(w > 0, "w", w == 0 ? "is required (orifice width in sigma_avg)" : "must be > 0, got " + num(w));
  require(W > 0, "W", "must be > 0, got " + num(W));
  require(w < W, "w", "must be smaller than the container width W = " + num(W) + ", got " + num(w));
  for (auto [name, th] : {std::pair{"theta_w_left_deg", theta_w_left_deg}, {"theta_w_right_deg", theta_w_right_deg}}) {
    require(th > 0 && th <= 90, name, "must be in (0, 90] degrees, got " + num(th));
  }
  if (dimension == 3)
    require(theta_w_left_deg == 90 && theta_w_right_deg == 90, "theta_w_deg",
            "the 3D hopper has a flat base only (90 degrees), got " + num(theta_w_left_deg));
  require(E_sp > 0, "E_sp", "must be > 0, got " + num(E_sp));
  require(E_w > 0, "E_w", "must be > 0, got " + num(E_w));
  require(zeta >= 0, "zeta", zeta == -1 ? "is required (viscous drag; 0 for friction only)" : "must be >= 0, got " + num(zeta));
  require(mu >= 0, "mu", mu == -1 ? "is required (kinetic friction; 0 for drag only)" : "must be >= 0, got " + num(mu));
  require(gravity >= 0, "gravity", "must be >= 0, got " + num(gravity));
  if (dt) require(*dt > 0, "dt", "must be > 0 or \"auto\", got " + num(*dt));
  require(max_overlap > 0 && max_overlap < 1, "max_overlap", "must be in (0, 1), got " + num(max_overlap));
  require(skin > 0 && skin <= 2.0, "skin", "must be in (0, 2], got " + num(skin));
  require(initial_packing_fraction > 0 && initial_packing_fraction <= 0.6, "initial_packing_fraction",
          "must be in (0, 0.6], got " + num(initial_packing_fraction));
  require(replica >= 0, "replica", "must be >= 0");
  require(fire.alpha0 > 0 && fire.alpha0 < 1, "fire.alpha0", "must be in (0, 1)");
  require(fire.f_inc > 1, "fire.f_inc", "must be > 1");
  require(fire.f_dec > 0 && fire.f_dec < 1, "fire.f_dec", "must be in (0, 1)");
  require(fire.f_alpha > 0 && fire.f_alpha < 1, "fire.f_alpha", "must be in (0, 1)");
  require(fire.n_min >= 0, "fire.n_min", "must be >= 0");
  require(fire.dt_max_factor >= 1, "fire.dt_max_factor", "must be >= 1");
  require(fire.force_tol > 0, "fire.force_tol", "must be > 0");
  require(fire.max_iter > 0, "fire.max_iter", "must be > 0");
  require(fire.max_pair_stiffness > 0, "fire.max_pair_stiffness", "must be > 0");
  require(run.t_max > 0, "run.t_max", "must be > 0, got " + num(run.t_max));
  require(run.target_rel_err > 0 && run.target_rel_err < 1, "run.target_rel_err", "must be in (0, 1)");
  require(run.t_clog > 0, "run.t_clog", "must be > 0");
  require(run.min_transient >= 0, "run.min_transient", "must be >= 0");
  require(run.min_window > 0, "run.min_window", "must be > 0");
  require(run.check_interval > 0, "run.check_interval", "must be > 0");
  require(run.rate_bin > 0, "run.rate_bin", "must be > 0");
  require(run.rate_bin <= run.min_window / 8, "run.rate_bin", "must be at most run.min_window / 8 (block averaging needs bins)");
  require(run.checkpoint_interval >= 0, "run.checkpoint_interval", "must be >= 0 (0: no checkpoints)");
  require(run.trajectory_every_steps >= 0, "run.trajectory_every_steps", "must be >= 0 (0: no trajectory)");
  require(reinjection.drop_depth_diameters >= 1, "reinjection.drop_depth_diameters", "must be >= 1");
  require(reinjection.top_band > 0, "reinjection.top_band", "must be > 0");
  require(reinjection.max_attempts >= 1, "reinjection.max_attempts", "must be >= 1");
  require(observables.sample_interval > 0, "observables.sample_interval", "must be > 0");
  require(observables.block_length >= observables.sample_interval, "observables.block_length",
          "must be >= observables.sample_interval");
  require(observables.profile_dh > 0, "observables.profile_dh", "must be > 0");
  require(observables.profile_h_max > observables.profile_dh, "observables.profile_h_max", "must be > observables.profile_dh");
  require(observables.kernel_width > 0, "observables.kernel_width", "must be > 0");
}

nlohmann::json SimConfig::to_json() const {
  json j;
  j["model"] = model;
  j["dimension"] = dimension;
  j["N"] = N;
  j["size_ratio"] = size_ratio;
  j["W"] = W;
  j["w"] = w;
  j["theta_w_left_deg"] = theta_w_left_deg;
  j["theta_w_right_deg"] = theta_w_right_deg;
  if (is_dp())
    j["dp"] = {{"n_v", dp.n_v}, {"K_a", dp.K_a}, {"K_l", dp.K_l}, {"K_b", dp.K_b}, {"E_c", dp.E_c}};
  else
    j["E_sp"] = E_sp;
  j["E_w"] = E_w;
  j["zeta"] = zeta;
  j["mu"] = mu;
  j["gravity"] = gravity;
  if (dt) j["dt"] = *dt; else j["dt"] = "auto";
  j["skin"] = skin;
  j["max_overlap"] = max_overlap;
  j["initial_packing_fraction"] = initial_packing_fraction;
  j["reinject"] = reinject;
  if (seed) j["seed"] = *seed;
  j["replica"] = replica;
  j["fire"] = {{"alpha0", fire.alpha0}, {"f_inc", fire.f_inc}, {"f_dec", fire.f_dec}, {"f_alpha", fire.f_alpha},
               {"n_min", fire.n_min}, {"dt_max_factor", fire.dt_max_factor}, {"force_tol", fire.force_tol},
               {"max_iter", fire.max_iter}, {"max_pair_stiffness", fire.max_pair_stiffness}};
  j["run"] = {{"t_max", run.t_max}, {"target_rel_err", run.target_rel_err}, {"t_clog", run.t_clog},
              {"min_transient", run.min_transient}, {"min_window", run.min_window},
              {"check_interval", run.check_interval}, {"rate_bin", run.rate_bin},
              {"checkpoint_interval", run.checkpoint_interval},
              {"trajectory_every_steps", run.trajectory_every_steps}};
  j["reinjection"] = {{"drop_depth_diameters", reinjection.drop_depth_diameters},
                      {"top_band", reinjection.top_band}, {"max_attempts", reinjection.max_attempts}};
  j["observables"] = {{"sample_interval", observables.sample_interval}, {"block_length", observables.block_length},
                      {"profile_dh", observables.profile_dh}, {"profile_h_max", observables.profile_h_max},
                      {"kernel_width", observables.kernel_width}};
  return j;
}

std::uint64_t SimConfig::effective_seed() const {
  if (seed) return *seed;
  // only what defines the trajectory: not the run controls, not the Verlet skin (the force
  // sums do not depend on it), not the blow-up threshold
  json j = to_json();
  j.erase("run");
  j.erase("seed");
  j.erase("skin");
  j.erase("max_overlap");
  return hash64(j.dump());
}

}  // namespace beverloo
