#pragma once
// A run resumed from a checkpoint file as `beverloo simulate --resume` resumes one: through
// prepare() (the checkpoint, then the flow's forces, gravity and lists), from a scratch
// directory of its own that is removed again once the state is loaded.
#include <filesystem>
#include <memory>
#include <string>

#include <unistd.h>

#include "engine/config.h"
#include "engine/protocol/hopper_run.h"

namespace beverloo::diagnostics {

inline std::unique_ptr<HopperRun<2>> resumed_run(const SimConfig& c, const std::filesystem::path& checkpoint,
                                                 const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / (name + "." + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy_file(checkpoint, dir / "checkpoint.h5", fs::copy_options::overwrite_existing);
  RunOptions options;
  options.output_dir = dir.string();
  options.resume = true;
  auto run = std::make_unique<HopperRun<2>>(c, options);
  run->prepare();
  fs::remove_all(dir);
  return run;
}

}  // namespace beverloo::diagnostics
