// `beverloo query DIR "SQL" [--format table|csv|json]`: read-only SQL over a campaign.
#include <chrono>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "guarded.h"
#include "core/failures.h"
#include "core/text_escape.h"
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
    case SQLITE_PRAGMA: {
      // reading a pragma (no argument) is fine, and so are the introspection pragmas, whose
      // argument names a table or index (also as table-valued functions: pragma_table_info('runs'));
      // setting one is not
      if (a2 == nullptr) return SQLITE_OK;
      static const char* introspection[] = {"table_info", "table_xinfo", "index_list", "index_info", "index_xinfo",
                                            "foreign_key_list", "table_list"};
      for (const char* name : introspection)
        if (a1 && sqlite3_stricmp(a1, name) == 0) return SQLITE_OK;
      return SQLITE_DENY;
    }
    case SQLITE_UPDATE:
      // SQLite asks for this when a table-valued pragma (pragma_table_info('runs')) is first
      // used: the eponymous virtual table's entry, not a write of ours (PRAGMA query_only and
      // the read-only check of every statement still hold)
      return a1 && std::strcmp(a1, "sqlite_master") == 0 ? SQLITE_OK : SQLITE_DENY;
    default:
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
      if (std::isnan(v)) return "nan";
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.10g", v);
      return buf;
    }
    case SQLITE_BLOB: {  // as SQL spells a blob: x'0a1b...'
      const auto* b = static_cast<const unsigned char*>(sqlite3_column_blob(st.handle(), i));
      const int n = sqlite3_column_bytes(st.handle(), i);
      std::string hex = "x'";
      char two[3];
      for (int k = 0; k < n; ++k) {
        std::snprintf(two, sizeof two, "%02x", b[k]);
        hex += two;
      }
      return hex + "'";
    }
    default: return st.get_text(i);
  }
}

/// Stops a query that runs longer than its time limit (a recursive CTE without end).
struct Deadline {
  std::chrono::steady_clock::time_point end;
  bool passed = false;
};
int past_deadline(void* p) {
  auto* d = static_cast<Deadline*>(p);
  d->passed = std::chrono::steady_clock::now() > d->end;
  return d->passed ? 1 : 0;  // non-zero interrupts the statement
}

int run_query(const std::string& dir, const std::string& sql, const std::string& format, double max_seconds,
              std::size_t max_rows) {
  try {
    CampaignReader reader(dir);
    db::Database& db = reader.db();
    db.exec("PRAGMA query_only = 1");
    sqlite3_set_authorizer(db.handle(), authorize, nullptr);
    // a query may not run forever nor take the machine's memory: a time limit checked every
    // 10^5 virtual-machine steps, a heap limit for SQLite, and a limit on the rows kept
    Deadline deadline{std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                             std::chrono::duration<double>(max_seconds))};
    sqlite3_progress_handler(db.handle(), 100000, past_deadline, &deadline);
    sqlite3_hard_heap_limit64(std::int64_t{2} << 30);
    // Prepare every statement first: one refused statement means nothing runs at all.
    std::vector<db::Statement> statements;
    const char* tail = sql.c_str();
    const char* end = tail + sql.size();
    while (tail < end) {
      sqlite3_stmt* raw = nullptr;
      const int rc = sqlite3_prepare_v2(db.handle(), tail, static_cast<int>(end - tail), &raw, &tail);
      if (rc != SQLITE_OK) {
        if ((rc & 0xff) == SQLITE_AUTH || std::strcmp(sqlite3_errmsg(db.handle()), "not authorized") == 0)
          std::fprintf(stderr, "beverloo query: refused: queries are read-only (SELECT, WITH, EXPLAIN, reading PRAGMAs "
                               "and table_info, index_list, ...; no writes, ATTACH or setting PRAGMAs); nothing ran\n");
        else
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
      std::vector<std::vector<double>> reals;
      bool more = false;
      try {
        while ((more = st.step())) {
          if (rows.size() == max_rows) break;
          std::vector<std::string> r;
          std::vector<int> t;
          std::vector<double> x;
          for (int i = 0; i < n; ++i) {
            t.push_back(st.column_type(i));
            x.push_back(t.back() == SQLITE_FLOAT ? st.get_double(i) : 0.0);
            r.push_back(cell(st, i));
          }
          rows.push_back(std::move(r));
          types.push_back(std::move(t));
          reals.push_back(std::move(x));
        }
      } catch (const db::DbError& e) {
        if (deadline.passed) {
          std::fprintf(stderr, "beverloo query: stopped after %g s (--max-seconds); nothing printed\n", max_seconds);
          return exit_code::kConfig;
        }
        if (e.code() == SQLITE_NOMEM) {
          std::fprintf(stderr, "beverloo query: the query needs more than SQLite's 2 GiB heap limit; nothing printed\n");
          return exit_code::kConfig;
        }
        throw;
      }
      if (more) {
        std::fprintf(stderr, "beverloo query: more than %zu rows (--max-rows); nothing printed; add a LIMIT or raise it\n",
                     max_rows);
        return exit_code::kConfig;
      }
      std::vector<std::string> names;
      for (int i = 0; i < n; ++i) names.push_back(st.column_name(i));
      if (format == "csv") {
        for (int i = 0; i < n; ++i) std::cout << (i ? "," : "") << csv_field(names[i]);
        std::cout << "\n";
        for (const auto& r : rows) {
          for (int i = 0; i < n; ++i) std::cout << (i ? "," : "") << csv_field(r[i]);
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
            else if (t == SQLITE_FLOAT && std::isfinite(reals[k][i])) o[names[i]] = reals[k][i];  // denormals too
            else if (t == SQLITE_FLOAT && std::isnan(reals[k][i])) o[names[i]] = nullptr;
            else o[names[i]] = rows[k][i];  // text (and "inf", "-inf", blobs as x'..')
          }
          out.push_back(o);
        }
        // bytes that are not UTF-8 become U+FFFD rather than abort the dump
        std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
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
    std::fprintf(stderr, "beverloo query: %s\n", terminal_safe(e.what()).c_str());
    return exit_code::kConfig;
  } catch (const db::DbError& e) {
    if ((e.code() & 0xff) == SQLITE_AUTH) {
      std::fprintf(stderr, "beverloo query: %s: queries are read-only (SELECT, WITH, EXPLAIN, reading PRAGMAs and "
                           "table_info, index_list, ...); nothing ran\n", terminal_safe(e.what()).c_str());
      return exit_code::kConfig;
    }
    std::fprintf(stderr, "beverloo query: %s\n", terminal_safe(e.what()).c_str());
    return exit_code::kIo;
  } catch (const std::exception& e) {  // not ours (ConfigError), busy, I/O: the shared table
    return guarded("query", [&]() -> int { throw; });
  }
}

}  // namespace

void add_query_command(CLI::App& app, int& exit_status) {
  struct Args {
    std::string dir, sql, format = "table";
    double max_seconds = 600;
    std::size_t max_rows = 1000000;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("query", "Read-only SQL over a campaign (docs/database.md)");
  cmd->add_option("DIR", a->dir, "campaign directory")->required();
  cmd->add_option("SQL", a->sql, "one or more SQL statements (read-only)")->required();
  cmd->add_option("--format", a->format, "table | csv | json")->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->add_option("--max-seconds", a->max_seconds, "stop a query that runs longer (default 600)")->check(CLI::PositiveNumber);
  cmd->add_option("--max-rows", a->max_rows, "refuse results longer than this (default 1000000)")->check(CLI::PositiveNumber);
  cmd->callback([a, &exit_status] {
    exit_status = run_query(a->dir, a->sql, a->format, a->max_seconds, a->max_rows);
  });
}

}  // namespace beverloo
