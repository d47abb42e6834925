#include "orchestrator/campaign/campaign_scope.h"

#include <charconv>
#include <system_error>

#include "core/errors.h"

namespace beverloo {

CampaignScope CampaignScope::parse(const std::string& text, const std::string& option) {
  if (text == "latest") return latest();
  if (text == "all") return all();
  // from_chars takes no sign or blank, and must consume the whole text without overflow
  std::int64_t id = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, id);
  if (error == std::errc() && stop == end && id > 0) return one(id);
  throw ConfigError(option + " '" + text + "'", "expected 'latest', 'all' or a campaign's id (a positive integer; "
                    "`beverloo query DIR \"SELECT id, name, created_at FROM campaigns\"` lists them)");
}

void CampaignScope::check_exists(db::Database& db, const std::string& option) const {
  if (kind_ != Kind::One) return;  // latest and all read what there is (nothing: an empty report)
  db::Statement st = db.prepare("SELECT count(*) FROM campaigns WHERE id = ?1");
  st.bind(1, id_);
  st.step();
  if (st.get_int(0) > 0) return;
  std::string ids;
  db::Statement list = db.prepare("SELECT id FROM campaigns ORDER BY id");
  while (list.step()) ids += (ids.empty() ? "" : ", ") + std::to_string(list.get_int(0));
  throw ConfigError(option + " " + std::to_string(id_), "no such campaign in this directory (" +
                    (ids.empty() ? std::string("it has none") : "its campaigns: " + ids) + ")");
}

std::string CampaignScope::condition_on(const std::string& column) const {
  switch (kind_) {
    case Kind::Latest: return column + " = (SELECT max(id) FROM campaigns)";
    case Kind::One: return column + " = " + std::to_string(id_);
    case Kind::All: break;
  }
  return column + " IS NOT NULL";
}

std::string CampaignScope::jobs_in_scope_sql() const {
  // a campaign's point_index stays far below 2^32; a job in several campaigns takes its place
  // in the first of them
  return "SELECT job_key, min(campaign_id * 4294967296 + point_index) AS ord FROM campaign_jobs WHERE " +
         condition_on("campaign_id") + " GROUP BY job_key";
}

std::string CampaignScope::latest_in_scope_sql() const {
  return "SELECT id, name, created_at FROM campaigns WHERE " + condition_on("id") + " ORDER BY id DESC LIMIT 1";
}

std::string CampaignScope::describe(db::Database& db) const {
  switch (kind_) {
    case Kind::Latest: return "the latest campaign";
    case Kind::One: return "campaign " + std::to_string(id_);
    case Kind::All: break;
  }
  return "every campaign (" + std::to_string(db.scalar_int("SELECT count(*) FROM campaigns")) + ")";
}

}  // namespace beverloo
