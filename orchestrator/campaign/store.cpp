#include "store.h"

#include "campaign_dir.h"
#include "core/digest.h"
#include "orchestrator/db/typed_columns.h"

#include "engine/parameters.h"
#include "core/version.h"

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <random>

namespace beverloo {

std::string new_token() {
  std::ifstream urandom("/dev/urandom", std::ios::binary);
  unsigned char bytes[16];
  if (!urandom.read(reinterpret_cast<char*>(bytes), sizeof bytes)) {
    std::random_device rd;
    for (auto& b : bytes) b = static_cast<unsigned char>(rd());
  }
  static const char* hex = "0123456789abcdef";
  std::string t;
  for (unsigned char b : bytes) {
    t += hex[b >> 4];
    t += hex[b & 15];
  }
  return t;
}

std::string host_name() {
  char buf[256] = {0};
  gethostname(buf, sizeof buf - 1);
  return buf;
}

std::int64_t CampaignStore::create_campaign(const Sweep& sweep, const std::string& sweep_text,
                                            const std::vector<JobSpec>& jobs) {
  db::Transaction tx(db_);
  const std::string sha = sha256_hex(sweep_text);
  std::int64_t id = -1;
  {
    db::Statement find = db_.prepare("SELECT id FROM campaigns WHERE name = ?1 AND sweep_sha256 = ?2");
    find.bind(1, sweep.name).bind(2, sha);
    if (find.step()) id = find.get_int(0);
  }
  if (id < 0) {
    db_.prepare("INSERT INTO campaigns (name, sweep_json, sweep_sha256) VALUES (?1, ?2, ?3)")
        .bind(1, sweep.name)
        .bind(2, sweep_text)
        .bind(3, sha)
        .run();
    id = db_.last_insert_rowid();
  }
  std::vector<const JobSpec*> all;
  all.reserve(jobs.size());
  for (const JobSpec& j : jobs) all.push_back(&j);
  insert_and_link(id, all, 0);
  tx.commit();
  return id;
}

void CampaignStore::insert_and_link(std::int64_t campaign, const std::vector<const JobSpec*>& jobs,
                                    std::int64_t point_index) {
  db::Statement insert_job = db_.prepare(db::jobs_insert_sql());  // the other parameter columns are generated
  db::Statement link = db_.prepare(
      "INSERT OR IGNORE INTO campaign_jobs (campaign_id, job_key, point_index, sweep_point) VALUES (?1, ?2, ?3, ?4)");
  std::int64_t index = point_index;
  for (const JobSpec* jp : jobs) {
    const JobSpec& j = *jp;
    const SimConfig& c = j.config;
    const std::optional<double> lambda = derived::lambda(c);  // NULL when there is no dissipation
    std::optional<double> scale;
    if (const double ds = derived::dissipation_scale(c); ds > 0) scale = ds;
    insert_job.bind(1, j.key)
        .bind(2, campaign_dir::job_dir_relative(j.key))
        .bind(3, j.job.dump())
        .bind(4, BEVERLOO_VERSION)
        .bind(5, lambda)
        .bind(6, scale);
    db::bind_parameter_columns(insert_job, c);
    insert_job.run();
    link.bind(1, campaign).bind(2, j.key).bind(3, index++).bind(4, j.point.dump()).run();
  }
}

void CampaignStore::record_decisions(std::int64_t campaign, const std::vector<PlanDecision>& decisions) {
  if (decisions.empty()) return;
  db::Transaction tx(db_);
  std::int64_t next_index = 0;
  {
    db::Statement st = db_.prepare("SELECT coalesce(max(point_index), -1) + 1 FROM campaign_jobs WHERE campaign_id = ?1");
    st.bind(1, campaign);
    st.step();
    next_index = st.get_int(0);
  }
  db::Statement seq = db_.prepare(
      "SELECT coalesce(max(seq), 0) + 1 FROM adaptive_decisions WHERE campaign_id = ?1 AND series_key = ?2");
  db::Statement row = db_.prepare(
      "INSERT INTO adaptive_decisions (campaign_id, series_key, seq, action, job_key, w, replica, reason, k_err, "
      "beta_err, k_err_after, beta_err_after, flowing_points) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, "
      "?12, ?13)");
  std::vector<const JobSpec*> added;
  for (const PlanDecision& d : decisions)
    if (d.job) added.push_back(&*d.job);
  insert_and_link(campaign, added, next_index);  // after the campaign's jobs, in decision order
  for (const PlanDecision& d : decisions) {
    seq.bind(1, campaign).bind(2, d.series_key);
    seq.step();
    const std::int64_t n = seq.get_int(0);
    seq.reset();
    row.bind(1, campaign).bind(2, d.series_key).bind(3, n).bind(4, d.action);
    if (d.job)
      row.bind(5, d.job->key).bind(6, d.job->config.w).bind(7, d.job->config.replica);
    else
      row.bind_null(5).bind_null(6).bind_null(7);
    row.bind(8, d.reason).bind(9, d.k_err).bind(10, d.beta_err).bind(11, d.k_err_after).bind(12, d.beta_err_after)
        .bind(13, d.flowing_points)
        .run();
  }
  tx.commit();
}

std::int64_t CampaignStore::latest_campaign() {
  db::Statement st = db_.prepare("SELECT max(id) FROM campaigns");
  return st.step() && !st.is_null(0) ? st.get_int(0) : -1;
}

std::vector<std::string> CampaignStore::continuation_sources(const std::string& key) {
  db::Statement mine = db_.prepare("SELECT job_json, seed, w, engine_version FROM jobs WHERE key = ?1");
  mine.bind(1, key);
  if (!mine.step()) return {};
  const nlohmann::json trajectory = SimConfig::from_json(nlohmann::json::parse(mine.get_text(0))).trajectory_json();
  // one trajectory has one seed and one w: the indexed columns narrow the search to a handful
  db::Statement st = db_.prepare(
      "SELECT j.dir, j.job_json FROM jobs j JOIN results r ON r.job_key = j.key "
      "WHERE j.seed = ?1 AND j.w = ?2 AND j.engine_version = ?3 AND j.key != ?4 AND j.state = 'done' AND r.clogged = 0 "
      "ORDER BY r.steps DESC, j.key");
  st.bind(1, mine.get_int(1));
  st.bind(2, mine.get_double(2));
  st.bind(3, mine.get_text(3));
  st.bind(4, key);
  std::vector<std::string> dirs;
  while (st.step()) {
    try {
      if (SimConfig::from_json(nlohmann::json::parse(st.get_text(1))).trajectory_json() == trajectory)
        dirs.push_back(st.get_text(0));
    } catch (const std::exception&) {
      // a stored job this engine cannot read is nobody's trajectory
    }
  }
  return dirs;
}

std::optional<ClaimedJob> CampaignStore::claim_next(std::int64_t campaign, const std::string& executor,
                                                    const std::string& host) {
  db::Transaction tx(db_);
  db::Statement pick = db_.prepare(
      "SELECT j.key, j.dir, j.job_json FROM jobs j JOIN campaign_jobs c ON c.job_key = j.key "
      "WHERE c.campaign_id = ?1 AND j.state = 'pending' AND j.engine_version = ?2 ORDER BY c.point_index LIMIT 1");
  pick.bind(1, campaign);
  pick.bind(2, BEVERLOO_VERSION);  // a job of another engine would be stored as its result
  if (!pick.step()) return std::nullopt;
  ClaimedJob a;
  a.key = pick.get_text(0);
  a.dir = pick.get_text(1);
  a.job_json = pick.get_text(2);
  pick.reset();
  db::Statement next = db_.prepare("SELECT coalesce(max(attempt_no), 0) + 1 FROM attempts WHERE job_key = ?1");
  next.bind(1, a.key);
  next.step();
  a.attempt_no = static_cast<int>(next.get_int(0));
  next.reset();
  a.token = new_token();
  db_.prepare("INSERT INTO attempts (job_key, attempt_no, token, executor, host, state) VALUES (?1, ?2, ?3, ?4, ?5, 'running')")
      .bind(1, a.key)
      .bind(2, a.attempt_no)
      .bind(3, a.token)
      .bind(4, executor)
      .bind(5, host)
      .run();
  a.attempt_id = db_.last_insert_rowid();
  db_.prepare("UPDATE jobs SET state = 'running' WHERE key = ?1").bind(1, a.key).run();
  tx.commit();
  return a;
}

void CampaignStore::set_attempt_pid(std::int64_t attempt_id, std::int64_t pid) {
  db_.prepare("UPDATE attempts SET pid = ?1 WHERE id = ?2").bind(1, pid).bind(2, attempt_id).run();
}

void CampaignStore::heartbeat(std::int64_t attempt_id) {
  db_.prepare("UPDATE attempts SET heartbeat_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE id = ?1")
      .bind(1, attempt_id)
      .run();
}

void CampaignStore::ingest_success(const ClaimedJob& a, const std::string& summary_json, const std::vector<double>& h,
                                   const std::vector<double>& v_g, const std::vector<double>& v_g_err) {
  const nlohmann::json s = nlohmann::json::parse(summary_json);
  db::Transaction tx(db_);
  db::Statement insert = db_.prepare(db::results_insert_sql());  // the stored fields of the result table
  insert.bind(1, a.key).bind(2, a.attempt_id);
  db::bind_result_columns(insert, s, summary_json);
  insert.run();
  const bool fresh = db_.changes() > 0;
  if (fresh) {
    db::Statement prof = db_.prepare("INSERT OR IGNORE INTO velocity_profiles (job_key, h, v_g, v_g_err) VALUES (?1, ?2, ?3, ?4)");
    for (std::size_t k = 0; k < h.size(); ++k) prof.bind(1, a.key).bind(2, h[k]).bind(3, v_g[k]).bind(4, v_g_err[k]).run();
  }
  db_.prepare("UPDATE attempts SET state = 'succeeded', exit_status = 0, ended_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') "
              "WHERE id = ?1 AND state = 'running'")
      .bind(1, a.attempt_id)
      .run();
  db_.prepare("UPDATE jobs SET state = CASE WHEN (SELECT clogged FROM results WHERE job_key = ?1) THEN 'clogged' ELSE 'done' END "
              "WHERE key = ?1")
      .bind(1, a.key)
      .run();
  tx.commit();
}

std::string CampaignStore::record_failure(std::int64_t attempt_id, const std::string& key, FailureClass cls,
                                          int exit_status, const std::string& message, int max_retries) {
  db::Transaction tx(db_);
  db_.prepare("UPDATE attempts SET state = ?1, failure_class = ?2, exit_status = ?3, message = ?4, "
              "ended_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE id = ?5")
      .bind(1, std::string(failure_info(cls).attempt_state))
      .bind(2, std::string(to_string(cls)))
      .bind(3, exit_status)
      .bind(4, message)
      .bind(5, attempt_id)
      .run();
  std::string state;
  {
    db::Statement st = db_.prepare("SELECT state, retries_used FROM jobs WHERE key = ?1");
    st.bind(1, key);
    st.step();
    state = st.get_text(0);
    const std::int64_t used = st.get_int(1);
    if (state == "done" || state == "clogged" || state == "cancelled") {
      tx.commit();
      return state;  // a result or a cancel arrived meanwhile: nothing to undo
    }
    switch (failure_info(cls).retry) {  // the one retry policy (core/failures.h)
      case RetryPolicy::Cancel: state = "cancelled"; break;  // a user cancelled it in the scheduler
      case RetryPolicy::Never: state = "failed"; break;
      case RetryPolicy::Budgeted: state = used >= max_retries ? "failed" : "pending"; break;
      case RetryPolicy::Free: state = "pending"; break;
    }
    st.reset();
    db_.prepare("UPDATE jobs SET state = ?1, retries_used = retries_used + ?2 WHERE key = ?3")
        .bind(1, state)
        .bind(2, is_infrastructure(cls) || state != "pending" ? 0 : 1)
        .bind(3, key)
        .run();
  }
  tx.commit();
  return state;
}

std::vector<RunningAttempt> CampaignStore::running_attempts() {
  std::vector<RunningAttempt> out;
  db::Statement st = db_.prepare(
      "SELECT a.id, a.job_key, j.dir, a.token, a.executor, coalesce(a.pid, -1), coalesce(a.slurm_submission, -1), "
      "coalesce(a.slurm_array_task, -1), j.job_json FROM attempts a JOIN jobs j ON j.key = a.job_key "
      "WHERE a.state = 'running' ORDER BY a.id");
  while (st.step())
    out.push_back({st.get_int(0), st.get_text(1), st.get_text(2), st.get_text(3), st.get_text(4), st.get_int(5), st.get_int(6),
                   static_cast<int>(st.get_int(7)), st.get_text(8)});
  return out;
}

std::int64_t CampaignStore::begin_submission(const std::string& name, int array_size, int throttle,
                                             const std::string& script, const std::string& sbatch_args_json,
                                             const std::vector<std::pair<std::int64_t, int>>& attempt_tasks) {
  db::Transaction tx(db_);
  db::Statement insert = db_.prepare(
      "INSERT INTO slurm_submissions (name, state, array_size, throttle, script, sbatch_args) VALUES (?1, 'submitting', ?2, ?3, ?4, ?5)");
  insert.bind(1, name).bind(2, array_size).bind(4, script).bind(5, sbatch_args_json);
  if (throttle > 0)
    insert.bind(3, throttle);
  else
    insert.bind_null(3);
  insert.run();
  const std::int64_t id = db_.last_insert_rowid();
  db::Statement link = db_.prepare("UPDATE attempts SET slurm_submission = ?1, slurm_array_task = ?2 WHERE id = ?3");
  for (const auto& [attempt, task] : attempt_tasks) link.bind(1, id).bind(2, task).bind(3, attempt).run();
  tx.commit();
  return id;
}

void CampaignStore::submission_done(std::int64_t submission, const std::string& slurm_job_id) {
  db::Transaction tx(db_);
  db_.prepare("UPDATE slurm_submissions SET state = 'submitted', slurm_job_id = ?1, "
              "submitted_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE id = ?2")
      .bind(1, slurm_job_id)
      .bind(2, submission)
      .run();
  db_.prepare("UPDATE attempts SET slurm_job_id = ?1 || '_' || slurm_array_task, slurm_state = coalesce(slurm_state, 'PENDING') "
              "WHERE slurm_submission = ?2")
      .bind(1, slurm_job_id)
      .bind(2, submission)
      .run();
  tx.commit();
}

void CampaignStore::submission_never_happened(std::int64_t submission, const std::string& message) {
  db_.prepare("UPDATE slurm_submissions SET state = 'never_submitted', message = ?1 WHERE id = ?2")
      .bind(1, message)
      .bind(2, submission)
      .run();
}

SlurmSubmission CampaignStore::submission(std::int64_t id) {
  db::Statement st = db_.prepare("SELECT id, name, state, coalesce(slurm_job_id, '') FROM slurm_submissions WHERE id = ?1");
  st.bind(1, id);
  if (!st.step()) return {};
  return {st.get_int(0), st.get_text(1), st.get_text(2), st.get_text(3)};
}

void CampaignStore::set_slurm_state(std::int64_t attempt_id, const std::string& state, int restarts) {
  db_.prepare("UPDATE attempts SET slurm_state = ?1, slurm_restarts = CASE WHEN ?2 >= 0 THEN ?2 ELSE slurm_restarts END WHERE id = ?3")
      .bind(1, state)
      .bind(2, restarts)
      .bind(3, attempt_id)
      .run();
}

void CampaignStore::heartbeat_at(std::int64_t attempt_id, double unix_seconds) {
  db_.prepare("UPDATE attempts SET heartbeat_at = strftime('%Y-%m-%dT%H:%M:%fZ', ?1, 'unixepoch') WHERE id = ?2")
      .bind(1, unix_seconds)
      .bind(2, attempt_id)
      .run();
}

StateCounts CampaignStore::counts(std::int64_t campaign) {
  StateCounts c;
  db::Statement st = db_.prepare(
      "SELECT j.state, count(*) FROM jobs j JOIN campaign_jobs c ON c.job_key = j.key WHERE c.campaign_id = ?1 GROUP BY j.state");
  st.bind(1, campaign);
  while (st.step()) {
    const std::string s = st.get_text(0);
    const std::int64_t n = st.get_int(1);
    if (s == "pending") c.pending = n;
    else if (s == "running") c.running = n;
    else if (s == "done") c.done = n;
    else if (s == "clogged") c.clogged = n;
    else if (s == "failed") c.failed = n;
    else if (s == "cancelled") c.cancelled = n;
  }
  return c;
}

std::int64_t CampaignStore::retry(std::int64_t campaign, bool include_cancelled) {
  db::Transaction tx(db_);
  db_.prepare(std::string("UPDATE jobs SET state = 'pending', retries_used = 0 WHERE key IN (SELECT job_key FROM campaign_jobs "
                          "WHERE campaign_id = ?1) AND engine_version = ?2 AND state IN ('failed'") +
              (include_cancelled ? ", 'cancelled')" : ")"))
      .bind(1, campaign)
      .bind(2, BEVERLOO_VERSION)
      .run();
  const std::int64_t n = db_.changes();
  tx.commit();
  return n;
}

std::int64_t CampaignStore::set_aside_other_engines(std::int64_t campaign) { return cancel_pending(campaign, true); }

std::int64_t CampaignStore::cancel(std::int64_t campaign) { return cancel_pending(campaign, false); }

std::int64_t CampaignStore::cancel_pending(std::int64_t campaign, bool other_engines_only) {
  db::Transaction tx(db_);
  db::Statement st = db_.prepare(std::string("UPDATE jobs SET state = 'cancelled' WHERE key IN (SELECT job_key FROM "
                                             "campaign_jobs WHERE campaign_id = ?1) AND state = 'pending'") +
                                 (other_engines_only ? " AND engine_version != ?2" : ""));
  st.bind(1, campaign);
  if (other_engines_only) st.bind(2, BEVERLOO_VERSION);
  st.run();
  const std::int64_t n = db_.changes();
  tx.commit();
  return n;
}

// The states of a job (the jobs table's CHECK); the runs view's status says how a done run ended.
const char* job_state_meaning(const std::string& state) {
  if (state == "done") return "finished; its result is stored (the runs view's status says how it ended)";
  if (state == "clogged") return "the flow stopped for good: no exit for run.t_clog (Q = 0, a result)";
  if (state == "failed") return "every attempt failed (blow-up, I/O); see the attempts table";
  if (state == "cancelled") return "cancelled by `beverloo campaign cancel`, or set aside as a job of another engine version";
  if (state == "running") return "an attempt is in flight";
  if (state == "pending") return "not started yet";
  return "";
}

}  // namespace beverloo
