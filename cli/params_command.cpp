// `beverloo params [--format table|markdown|json|schema-defs]`: the table of job parameters
// (engine/parameters), the one place each parameter is described; with --results the table of
// a run's result fields (engine/protocol/result_fields).
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "engine/parameters.h"
#include "engine/protocol/result_fields.h"
#include "core/failures.h"
#include "orchestrator/sweep/sweep_schema.h"

namespace beverloo {
namespace {

void print_result_fields(const std::string& format) {
  if (format == "markdown") {
    std::cout << result_fields_markdown();
  } else if (format == "json") {
    nlohmann::json rows = nlohmann::json::array();
    for (const ResultField& f : result_fields())
      rows.push_back({{"name", f.name}, {"sql_type", f.sql_type()}, {"unit", f.unit}, {"doc", f.doc},
                      {"result_h5", h5_group_name(f.h5_group)}, {"summary_json", f.in_summary}, {"sql", sql_kind_name(f.sql)},
                      {"runs_view", f.in_runs_view}});
    std::cout << rows.dump(2) << "\n";
  } else if (format == "schema-defs") {
    std::cerr << "beverloo params: --results has no schema-defs (result fields are not sweep input)\n";
  } else {
    for (const ResultField& f : result_fields())
      std::cout << std::left << std::setw(27) << f.name << std::setw(19) << f.unit << std::setw(9) << h5_group_name(f.h5_group)
                << std::setw(11) << sql_kind_name(f.sql) << f.doc << "\n";
  }
}

}  // namespace

void add_params_command(CLI::App& app, int& exit_status) {
  auto* cmd = app.add_subcommand("params", "The job parameters: unit, default, valid range, sweepable, key, SQL column");
  auto format = std::make_shared<std::string>("table");
  auto results = std::make_shared<bool>(false);
  cmd->add_flag("--results", *results,
                "The result fields instead: unit, result.h5 group, summary.json, SQL column, runs view (docs/database.md)");
  cmd->add_option("--format", *format, "table | markdown (docs/job-file.md) | json | schema-defs (schema/sweep.schema.json)")
      ->check(CLI::IsMember({"table", "markdown", "json", "schema-defs"}));
  cmd->callback([format, results, &exit_status] {
    if (*results) {
      print_result_fields(*format);
      exit_status = *format == "schema-defs" ? exit_code::kConfig : exit_code::kOk;
      return;
    }
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
