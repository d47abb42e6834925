#pragma once
/// \file commands.h
/// \brief Subcommand registration: each adds itself to the CLI11 app.
#include <CLI/CLI.hpp>

namespace beverloo {
/// Each returns a function that runs the command after parsing and returns the exit code.
void add_simulate_command(CLI::App& app, int& exit_status);
void add_bench_command(CLI::App& app, int& exit_status);
void add_campaign_commands(CLI::App& app, int& exit_status);
void add_query_command(CLI::App& app, int& exit_status);
void add_report_commands(CLI::App& app, int& exit_status);
void add_params_command(CLI::App& app, int& exit_status);
void add_experiment_command(CLI::App& app, int& exit_status);
/// `beverloo report` for a campaign directory; also the last step of `beverloo run`.
int report_campaign(const std::string& dir, const std::string& out, const std::string& campaign = "latest");
}  // namespace beverloo
