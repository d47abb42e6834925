// `beverloo query DIR "SQL" [--format table|csv|json]`: read-only SQL over a campaign.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/failures.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "orchestrator/db/database.h"
#include "orchestrator/db/migrations.h"

namespace beverloo {
namespace {

/// Refuses everything that could change the database or reach another one.
int authorize(void*, int action, const char* a1, const char* a2, const char*, const char*) {
  switch (action) {
    case SQLITE_SELECT: case SQLITE_READ: case SQLITE_FUNCTION: case SQLITE_RECURSIVE:
      return SQLITE_OK;
    case SQLITE_PRAGMA:
      // reading a pragma (no argument) is fine; setting one is not
      return a2 == nullptr ? SQLITE_OK : SQLITE_DENY;
    default:
      (void)a1;
      return SQLITE_DENY;  // INSERT, UPDATE, DELETE, CREATE, DROP, ALTER, ATTACH, DETACH, TRANSACTION, ...
  }
}

std::string cell(db::Statement& st, int i) {
  switch (st.column_type(i)) {
    case SQLITE_NULL: return "";
    case SQLITE_INTEGER: return std::to_string(st.get_int(i));
    case SQLITE_FLOAT: {
      const double v = st.get_double(i);
      if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.10g", v);
      return buf;
    }
    default: return st.get_text(i);
  }
}

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

int run_query(const std::string& dir, const std::string& sql, const std::string& format) {
  try {
    CampaignReader reader(dir);
    db::Database& db = reader.db();
    db.exec("PRAGMA query_only = 1");
    sqlite3_set_authorizer(db.handle(), authorize, nullptr);
    // Prepare every statement first: one refused statement means nothing runs at all.
    std::vector<db::Statement> statements;
    const char* tail = sql.c_str();
    const char* end = tail + sql.size();
    while (tail < end) {
      sqlite3_stmt* raw = nullptr;
      const int rc = sqlite3_prepare_v2(db.handle(), tail, static_cast<int>(end - tail), &raw, &tail);
      if (rc != SQLITE_OK) {
        std::fprintf(stderr, "beverloo query: %s\n", sqlite3_errmsg(db.handle()));
        return exit_code::kConfig;
      }
      if (!raw) continue;  // whitespace or a comment
      statements.emplace_back(db, raw);
      if (!statements.back().readonly()) {
        std::fprintf(stderr, "beverloo query: refused: only read-only statements are allowed\n");
        return exit_code::kConfig;
      }
    }
    for (db::Statement& st : statements) {
      const int n = st.columns();
      std::vector<std::vector<std::string>> rows;
      std::vector<std::vector<int>> types;
      while (st.step()) {
        std::vector<std::string> r;
        std::vector<int> t;
        for (int i = 0; i < n; ++i) {
          r.push_back(cell(st, i));
          t.push_back(st.column_type(i));
        }
        rows.push_back(std::move(r));
        types.push_back(std::move(t));
      }
      std::vector<std::string> names;
      for (int i = 0; i < n; ++i) names.push_back(st.column_name(i));
      if (format == "csv") {
        for (int i = 0; i < n; ++i) std::cout << (i ? "," : "") << csv_quote(names[i]);
        std::cout << "\n";
        for (const auto& r : rows) {
          for (int i = 0; i < n; ++i) std::cout << (i ? "," : "") << csv_quote(r[i]);
          std::cout << "\n";
        }
      } else if (format == "json") {
        nlohmann::json out = nlohmann::json::array();
        for (std::size_t k = 0; k < rows.size(); ++k) {
          nlohmann::json o = nlohmann::json::object();
          for (int i = 0; i < n; ++i) {
            const int t = types[k][i];
            if (t == SQLITE_NULL) o[names[i]] = nullptr;
            else if (t == SQLITE_INTEGER) o[names[i]] = std::stoll(rows[k][i]);
            else if (t == SQLITE_FLOAT && rows[k][i].find("inf") == std::string::npos) o[names[i]] = std::stod(rows[k][i]);
            else o[names[i]] = rows[k][i];
          }
          out.push_back(o);
        }
        std::cout << out.dump(2) << "\n";
      } else {
        std::vector<std::size_t> width(n);
        for (int i = 0; i < n; ++i) width[i] = names[i].size();
        for (const auto& r : rows)
          for (int i = 0; i < n; ++i) width[i] = std::max(width[i], r[i].size());
        auto line = [&](const std::vector<std::string>& r) {
          for (int i = 0; i < n; ++i) std::printf("%s%-*s", i ? "  " : "", static_cast<int>(width[i]), r[i].c_str());
          std::printf("\n");
        };
        line(names);
        std::vector<std::string> rule;
        for (int i = 0; i < n; ++i) rule.push_back(std::string(width[i], '-'));
        line(rule);
        for (const auto& r : rows) line(r);
        std::printf("(%zu rows)\n", rows.size());
      }
    }
    return exit_code::kOk;
  } catch (const MissingCampaign& e) {
    std::fprintf(stderr, "beverloo query: %s\n", e.what());
    return exit_code::kConfig;
  } catch (const db::DbError& e) {
    std::fprintf(stderr, "beverloo query: %s\n", e.what());
    return e.code() == SQLITE_AUTH ? exit_code::kConfig : exit_code::kIo;
  }
}

}  // namespace

void add_query_command(CLI::App& app, int& exit_status) {
  struct Args {
    std::string dir, sql, format = "table";
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("query", "Read-only SQL over a campaign (docs/database.md)");
  cmd->add_option("DIR", a->dir, "campaign directory")->required();
  cmd->add_option("SQL", a->sql, "one or more SQL statements (read-only)")->required();
  cmd->add_option("--format", a->format, "table | csv | json")->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->callback([a, &exit_status] { exit_status = run_query(a->dir, a->sql, a->format); });
}

}  // namespace beverloo
