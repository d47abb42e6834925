#include "job_speed.h"

#include <map>

namespace beverloo {

std::vector<ModelSpeed> campaign_speed(db::Database& db, const CampaignScope& scope) {
  db::Statement st = db.prepare(std::string("SELECT j.model || ' ' || j.dimension || 'D', ") + kT0PerCpuMinuteSql +
                                " FROM results r JOIN (" + scope.jobs_in_scope_sql() + ") cj ON cj.job_key = r.job_key JOIN jobs j ON "
                                "j.key = r.job_key WHERE r.wall_seconds > 0 AND "
                                "json_extract(r.summary_json, '$.t_end') > 0 ORDER BY 1, 2");
  std::map<std::string, std::vector<double>> by_model;  // each list ascending (ORDER BY)
  while (st.step()) by_model[st.get_text(0)].push_back(st.get_double(1));
  std::vector<ModelSpeed> out;
  for (const auto& [model, v] : by_model) {
    const std::size_t n = v.size();
    const double median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    out.push_back({model, static_cast<int>(n), median, v.front(), v.back()});
  }
  return out;
}

}  // namespace beverloo
