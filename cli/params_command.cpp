// `beverloo params [--format table|markdown|json|schema-defs]`: the table of job parameters
// (engine/parameters), the one place each parameter is described.
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "engine/parameters.h"
#include "core/failures.h"
#include "orchestrator/sweep/sweep_schema.h"

namespace beverloo {

void add_params_command(CLI::App& app, int& exit_status) {
  auto* cmd = app.add_subcommand("params", "The job parameters: unit, default, valid range, sweepable, key, SQL column");
  auto format = std::make_shared<std::string>("table");
  cmd->add_option("--format", *format, "table | markdown (docs/job-file.md) | json | schema-defs (schema/sweep.schema.json)")
      ->check(CLI::IsMember({"table", "markdown", "json", "schema-defs"}));
  cmd->callback([format, &exit_status] {
    if (*format == "markdown") {
      std::cout << parameters_markdown();
    } else if (*format == "schema-defs") {
      std::cout << parameter_schema_defs().dump(2) << "\n";
    } else if (*format == "json") {
      nlohmann::json rows = nlohmann::json::array();
      for (const ParamSpec& p : job_parameters())
        rows.push_back({{"path", p.path}, {"unit", p.unit}, {"default", p.default_text}, {"valid", p.rule_text()},
                        {"doc", p.doc}, {"sweepable", p.sweepable}, {"in_key", p.in_key},
                        {"sql_column", p.sql_column}});
      std::cout << rows.dump(2) << "\n";
    } else {
      for (const ParamSpec& p : job_parameters())
        std::cout << std::left << std::setw(36) << p.path << std::setw(26) << p.unit << std::setw(22) << p.default_text
                  << p.rule_text() << "\n";
    }
    exit_status = exit_code::kOk;
  });
}

}  // namespace beverloo
