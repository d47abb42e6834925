#include "result_file.h"
#include "core/atomic_file.h"

#include <type_traits>
#include <variant>

#include "../parameters.h"
#include "../protocol/result_fields.h"

#include "h5.h"
#include "core/version.h"

namespace beverloo {
namespace {

/// A group of result.h5 whose attributes are the rows of the result-field table that live there
/// (booleans as 0/1).
void write_result_group(hid_t file, const char* name, ResultGroup which, const RunResult& r) {
  H5Handle g = h5::create_group(file, name);
  for (const ResultField& field : result_fields()) {
    if (field.h5_group != which) continue;
    const std::string attr_name(field.name);
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, double> || std::is_same_v<V, std::string>)
            h5::attr(g, attr_name, v);
          else
            h5::attr(g, attr_name, static_cast<std::int64_t>(v));  // integers, booleans
        },
        field.get(r));
  }
}

/// Every row of the parameter table that applies to the job's model, under its JSON path
/// ("E_sp", "dp.K_l", "run.t_max"; booleans and integers as int64), resolved: seed and dt as
/// the run used them; an optional field left unset (mu_n, ...) is not written. Beside them
/// lambda (= drag / friction, inf without friction; docs/sweeps.md), which is derived.
void write_parameter_attributes(hid_t p, const SimConfig& job, const RunResult& r) {
  SimConfig c = job;  // the accessors are shared with the reader and take a mutable config
  for (const ParamSpec& row : job_parameters()) {
    if (!parameter_applies(row.models, c.model) || row.path == "theta_w_deg") continue;  // both sides are rows
    const std::string name(row.path);
    const ParamAccess& a = row.access;
    switch (row.type) {
      case ParamType::Real: h5::attr(p, name, a.real(c)); break;
      case ParamType::OptionalReal:
        if (a.optional_real(c)) h5::attr(p, name, *a.optional_real(c));
        break;
      case ParamType::Integer: h5::attr(p, name, std::int64_t{a.integer(c)}); break;
      case ParamType::Integer64: h5::attr(p, name, a.integer64(c)); break;
      case ParamType::Boolean: h5::attr(p, name, std::int64_t{a.boolean(c)}); break;
      case ParamType::Text: h5::attr(p, name, a.text(c)); break;
      case ParamType::RealOrAuto: h5::attr(p, name, r.dt); break;  // dt: "auto" resolved
      case ParamType::Seed: h5::attr(p, name, static_cast<std::int64_t>(r.seed)); break;
    }
  }
  h5::attr(p, "lambda", derived::lambda(c).value_or(INFINITY));
}

}  // namespace

void write_result_file(const std::string& path, const SimConfig& c, const RunResult& r) {
  PendingFile file(path);  // removed if anything below fails (a full disk)
  {
    H5Handle f = h5::create_file(file.path());
    h5::attr(f, "format", std::string("beverloo-result"));
    h5::attr(f, "format_version", std::int64_t{1});
    h5::attr(f, "engine_version", std::string(BEVERLOO_VERSION));
    {
      H5Handle p = h5::create_group(f, "parameters");
      h5::attr(p, "job_json", c.to_json().dump());
      write_parameter_attributes(p, c, r);
    }
    write_result_group(f, "result", ResultGroup::Result, r);
    {
      H5Handle g = h5::create_group(f, "exits");
      h5::write(g, "time", r.exit_time);
      h5::write(g, "size", r.exit_size);
      h5::write(g, "particle", r.exit_particle);
    }
    if (r.draining) {  // only then: a continuous run's file keeps its layout
      H5Handle g = h5::create_group(f, "drain");
      h5::attr(g, "n_initial", std::int64_t{r.n_initial});
      h5::attr(g, "n_remaining", std::int64_t{r.n_remaining});
      h5::attr(g, "fit_ok", std::int64_t{r.drain.ok});
      h5::attr(g, "fit_message", r.drain.message);
      h5::attr(g, "c0", r.drain.c0);
      h5::attr(g, "c0_err", r.drain.c0_err);
      h5::attr(g, "chi2_red", r.drain.chi2_red);
      h5::attr(g, "exits_used", std::int64_t{r.drain.exits_used});
      // N(t): the hopper's count just after each exit, and the fitted blocks
      std::vector<double> n_after(r.exit_time.size());
      for (std::size_t k = 0; k < n_after.size(); ++k) n_after[k] = double(r.n_initial) - double(k) - 1;
      h5::write(g, "N_after_exit", n_after);
      h5::write(g, "block_N", r.drain.block_N);
      h5::write(g, "block_rate", r.drain.block_rate);
      h5::write(g, "block_rate_err", r.drain.block_rate_err);
    }
    {
      H5Handle g = h5::create_group(f, "rate");
      h5::attr(g, "bin_width", r.rate_bin);
      h5::write(g, "value", r.rate);
    }
    {
      H5Handle g = h5::create_group(f, "profile");
      h5::write(g, "h", r.profile_h);
      h5::write(g, "v_g", r.profile_v_g);
      h5::write(g, "v_g_err", r.profile_v_g_err);
    }
    {
      H5Handle g = h5::create_group(f, "clog_events");
      std::vector<double> times, detected;
      if (r.clogged) {
        times.push_back(r.clog_time);
        detected.push_back(r.clog_detected_time);
      }
      h5::write(g, "time", times);
      h5::write(g, "detected_time", detected);
    }
    write_result_group(f, "run", ResultGroup::Run, r);
    h5::flush(f, file.path());  // a flush that failed leaves an incomplete file: not committed
  }
  file.commit();
}

}  // namespace beverloo
