#pragma once
/// \file campaign_scope.h
/// \brief Which campaigns of a directory `fit` and `report` read. A directory holds one campaign
/// per sweep text run in it; a job shared by several (the same key) is one job. The default is
/// the latest campaign, as before this option existed; `all` reads every job of every campaign
/// once, so that a report covers a sweep and its later extensions (more replicas, a lambda
/// added) without a sweep file that repeats them all.
#include <cstdint>
#include <string>

#include "orchestrator/db/database.h"

namespace beverloo {

class CampaignScope {
 public:
  static CampaignScope latest() { return CampaignScope(Kind::Latest, -1); }
  static CampaignScope all() { return CampaignScope(Kind::All, -1); }
  static CampaignScope one(std::int64_t id) { return CampaignScope(Kind::One, id); }
  /// "latest", "all" or a campaign's id (a positive integer); anything else throws ConfigError
  /// naming `option` and what it accepts.
  static CampaignScope parse(const std::string& text, const std::string& option);

  /// Throws ConfigError when the database has no campaign this scope can read (an id that is
  /// not there, or no campaign at all for `one`), naming `option` and the ids that exist.
  void check_exists(db::Database& db, const std::string& option) const;

  /// A SQL expression true for the campaign ids in scope: `column` is the id column to test
  /// (an id is an integer, so the text is never user text).
  std::string condition_on(const std::string& column) const;
  /// SELECT of each job key in scope once, with `ord`: the job's place (its first campaign,
  /// then its place in that campaign's sweep), the order series and points are read in.
  std::string jobs_in_scope_sql() const;
  /// The campaign whose name and creation time head the report: the latest in scope.
  std::string latest_in_scope_sql() const;
  /// "the latest campaign", "campaign 3", "every campaign (N)": for messages and the report.
  std::string describe(db::Database& db) const;

  bool is_all() const { return kind_ == Kind::All; }

 private:
  enum class Kind { Latest, One, All };
  CampaignScope(Kind kind, std::int64_t id) : kind_(kind), id_(id) {}
  Kind kind_;
  std::int64_t id_;
};

}  // namespace beverloo
