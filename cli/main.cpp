// beverloo: hopper flows of soft and deformable particles. One binary, subcommands.
#include <iostream>

#include "commands.h"
#include "engine/io/h5.h"
#include "core/failures.h"
#include "core/version.h"

int main(int argc, char** argv) {
  beverloo::h5::init_library();
  CLI::App app{"beverloo " BEVERLOO_VERSION " - hopper flows of soft and deformable particles"};
  app.require_subcommand(1);
  app.set_version_flag("--version", BEVERLOO_VERSION);
  int status = beverloo::exit_code::kOk;
  beverloo::add_simulate_command(app, status);
  beverloo::add_bench_command(app, status);
  beverloo::add_campaign_commands(app, status);
  beverloo::add_query_command(app, status);
  beverloo::add_report_commands(app, status);
  beverloo::add_params_command(app, status);
  beverloo::add_experiment_command(app, status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : beverloo::exit_code::kConfig;
  }
  return status;
}
