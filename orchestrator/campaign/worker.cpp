#include "worker.h"

#include <filesystem>
#include <fstream>

#include "engine/io/h5.h"
#include "engine/protocol/hopper_run.h"
#include "job_files.h"
#include "orchestrator/cli/exit_codes.h"
#include "orchestrator/cli/signals.h"

namespace beverloo {
namespace fs = std::filesystem;

int run_worker(const std::string& spec_path) {
  const std::string dir = fs::path(spec_path).parent_path().string();
  nlohmann::json spec;
  {
    std::ifstream in(spec_path);
    if (!in) {
      std::fprintf(stderr, "beverloo worker: cannot read %s\n", spec_path.c_str());
      return exit_code::kIo;
    }
    spec = nlohmann::json::parse(in);
  }
  job_files::Outcome out;
  out.token = spec.at("token");
  out.attempt_no = spec.at("attempt_no");
  auto finish = [&](int code, const char* cls, const std::string& message) {
    out.exit_code = code;
    out.failure_class = cls;
    out.message = message;
    try {
      job_files::write_outcome(dir, out);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "beverloo worker: cannot write the outcome: %s\n", e.what());
      return exit_code::kIo;
    }
    if (!message.empty()) std::fprintf(stderr, "beverloo worker: %s\n", message.c_str());
    return code;
  };
  SimConfig c;
  try {
    c = SimConfig::from_json(spec.at("job"));
  } catch (const ConfigError& e) {
    return finish(exit_code::kConfig, "invalid_parameters", e.what());
  }
  try {
    // A previous attempt may have finished the run and died before writing its outcome.
    const fs::path result = fs::path(dir) / "result.h5";
    if (fs::exists(result) && fs::exists(fs::path(dir) / "summary.json")) {
      H5Handle f = h5::open_file(result.string());
      H5Handle p = h5::open_group(f, "parameters");
      if (h5::attr_string(p, "job_json") == c.to_json().dump()) return finish(exit_code::kOk, "", "");
    }
    RunOptions opt;
    opt.output_dir = dir;
    opt.resume = true;
    opt.progress = ProgressMode::Log;
    opt.stop_request = install_stop_handlers();
    const RunResult r = run_hopper(c, opt);
    if (r.status == "interrupted") return finish(exit_code::kInterrupted, "interrupted", r.stop_reason);
    return finish(exit_code::kOk, "", "");
  } catch (const ConfigError& e) {
    return finish(exit_code::kConfig, "invalid_parameters", e.what());
  } catch (const InstabilityError& e) {
    return finish(exit_code::kUnstable, "blow_up", e.what());
  } catch (const IoError& e) {
    return finish(exit_code::kIo, "io", e.what());
  } catch (const std::exception& e) {
    return finish(exit_code::kInternal, "internal", e.what());
  }
}

}  // namespace beverloo
