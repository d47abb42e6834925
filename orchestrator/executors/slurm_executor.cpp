#include "slurm_executor.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "engine/models/model_time_step.h"
#include "core/atomic_file.h"
#include "orchestrator/campaign/job_files.h"

namespace beverloo {
namespace fs = std::filesystem;

namespace {

/// Particle (or vertex) steps per second of one core: a little below the bench cases (SP 2.7-3.3e7,
/// smooth DP 1.3e7), so that estimates err on the long side.
constexpr double kPointStepsPerSecond = 1.0e7;
constexpr int kMaxJobsPerTask = 100;

double steady_now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
double unix_now() { return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count(); }

std::string first_line(const std::string& text) {
  std::string s = text.substr(0, text.find('\n'));
  return s.empty() ? text : s;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

SlurmExecutor::SlurmExecutor(CampaignStore& store, std::string campaign_dir, SlurmOptions options)
    : store_(store), dir_(std::move(campaign_dir)), options_(std::move(options)) {
  if (options_.worker_binary.empty()) options_.worker_binary = fs::read_symlink("/proc/self/exe").string();
  poll_interval_ = options_.poll_min_s;
  started_at_ = steady_now();
  detect_cluster();
}

SlurmExecutor::~SlurmExecutor() {
  if (commands_.total() == 0) return;
  const double minutes = (steady_now() - started_at_) / 60;
  std::string by;
  for (const auto& [name, n] : commands_.calls()) by += (by.empty() ? "" : ", ") + name + " " + std::to_string(n);
  std::fprintf(stderr, "[beverloo] slurm: %d commands in %.1f min (%.1f per minute): %s\n", commands_.total(), minutes,
               minutes > 0 ? commands_.total() / minutes : 0.0, by.c_str());
}

void SlurmExecutor::detect_cluster() {
  const slurm::CommandResult r = commands_.run({"scontrol", "show", "config"});
  if (r.rc != 0)
    throw std::runtime_error("cannot reach Slurm (scontrol show config: " + first_line(r.text()) +
                             "); is this a cluster's login node?");
  const auto config = slurm::parse_config(r.out);
  auto get = [&](const char* k) { auto it = config.find(k); return it == config.end() ? std::string() : it->second; };
  have_sacct_ = get("AccountingStorageType").find("slurmdbd") != std::string::npos;
  if (get("JobCompType") == "jobcomp/filetxt") jobcomp_path_ = get("JobCompLoc");
  int cluster_max = 1001;
  try {
    cluster_max = std::stoi(get("MaxArraySize"));
  } catch (const std::exception&) { /* keep Slurm's default */ }
  max_array_ = std::min(cluster_max - 1, 1000);
  if (options_.max_array > 0) max_array_ = std::min(options_.max_array, cluster_max - 1);
  if (max_array_ < 1) throw std::runtime_error("MaxArraySize of this cluster allows no job arrays");
}

double SlurmExecutor::estimated_seconds(const std::string& job_json) {
  try {
    const SimConfig c = SimConfig::from_json(nlohmann::json::parse(job_json));
    const double dt = choose_time_step(c).dt;
    const double points = std::max(c.N, 1) * (c.is_dp() ? c.dp.n_v : 1);
    return points * (c.run.t_max / dt) / kPointStepsPerSecond;
  } catch (const std::exception&) {
    return INFINITY;  // unknown cost: a task of its own
  }
}

std::vector<std::vector<std::size_t>> SlurmExecutor::bundle_jobs(const std::vector<double>& estimated_s, int bundle,
                                                                 double target_s) {
  std::vector<std::vector<std::size_t>> tasks;
  double load = 0;
  for (std::size_t i = 0; i < estimated_s.size(); ++i) {
    const bool full = tasks.empty() || (bundle > 0 ? static_cast<int>(tasks.back().size()) >= bundle
                                                   : (load + estimated_s[i] > target_s ||
                                                      static_cast<int>(tasks.back().size()) >= kMaxJobsPerTask));
    if (full) {
      tasks.emplace_back();
      load = 0;
    }
    tasks.back().push_back(i);
    load += estimated_s[i];
  }
  return tasks;
}

void SlurmExecutor::start(const std::vector<ClaimedJob>& jobs) {
  std::vector<double> est;
  for (const ClaimedJob& j : jobs) est.push_back(estimated_seconds(j.job_json));
  const auto tasks = bundle_jobs(est, options_.bundle, options_.bundle_target_s);
  for (std::size_t first = 0; first < tasks.size(); first += static_cast<std::size_t>(max_array_)) {
    const std::size_t last = std::min(tasks.size(), first + static_cast<std::size_t>(max_array_));
    submit_chunk(jobs, std::vector<std::vector<std::size_t>>(tasks.begin() + first, tasks.begin() + last));
  }
}

void SlurmExecutor::submit_chunk(const std::vector<ClaimedJob>& jobs, const std::vector<std::vector<std::size_t>>& tasks) {
  const std::string name = "beverloo-" + new_token().substr(0, 16);
  const fs::path sub_dir = fs::path(dir_) / "slurm" / name;
  fs::create_directories(sub_dir);
  const int size = static_cast<int>(tasks.size());
  std::string array = "0-" + std::to_string(size - 1);
  if (options_.throttle > 0) array += "%" + std::to_string(options_.throttle);
  std::vector<std::string> args = {"sbatch", "--parsable", "--job-name=" + name, "--array=" + array,
                                   "--output=" + (sub_dir / "%A_%a.out").string(), "--open-mode=append",
                                   "--signal=B:USR1@" + std::to_string(options_.signal_lead_s), "--requeue",
                                   "--ntasks=1", "--cpus-per-task=" + std::to_string(options_.cpus_per_task),
                                   "--chdir=" + dir_};
  if (!options_.partition.empty()) args.push_back("--partition=" + options_.partition);
  if (!options_.time_limit.empty()) args.push_back("--time=" + options_.time_limit);
  for (const std::string& a : options_.sbatch_args) args.push_back(a);
  args.push_back((sub_dir / "job.sh").string());

  // 1. the intent, before anything reaches Slurm: a coordinator killed from here on finds it
  std::vector<std::pair<std::int64_t, int>> attempt_tasks;
  nlohmann::json manifest_tasks = nlohmann::json::array();
  std::vector<Tracked> watch;
  for (int t = 0; t < size; ++t) {
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t j : tasks[static_cast<std::size_t>(t)]) {
      attempt_tasks.emplace_back(jobs[j].attempt_id, t);
      entries.push_back({{"dir", jobs[j].dir}, {"token", jobs[j].token}});
      Tracked tr;
      tr.attempt_id = jobs[j].attempt_id;
      tr.dir = (fs::path(dir_) / jobs[j].dir).string();
      tr.token = jobs[j].token;
      tr.task = t;
      watch.push_back(tr);
    }
    manifest_tasks.push_back(entries);
  }
  const std::string script_rel = (fs::path("slurm") / name / "job.sh").string();
  const std::int64_t sub = store_.begin_submission(name, size, options_.throttle, script_rel, nlohmann::json(args).dump(), attempt_tasks);
  submission_names_[sub] = name;
  for (Tracked& tr : watch) {
    tr.submission = sub;
    tracked_[tr.attempt_id] = tr;
  }
  // 2. the files the tasks read
  write_text_atomically((sub_dir / "manifest.json").string(),
                        nlohmann::json{{"root", dir_}, {"submission", name}, {"tasks", manifest_tasks}}.dump() + "\n");
  const std::string script =
      "#!/bin/sh\n"
      "# beverloo: Slurm array " + name + " of the campaign in " + dir_ + ", written by the coordinator.\n"
      "# Array task i runs the attempts of line i of manifest.json. exec: the worker becomes the batch\n"
      "# shell, so that --signal=B:USR1@lead reaches it and it checkpoints before the time limit.\n"
      "exec " + shell_quote(options_.worker_binary) + " worker --manifest " + shell_quote((sub_dir / "manifest.json").string()) +
      " --task \"$SLURM_ARRAY_TASK_ID\"\n";
  write_text_atomically((sub_dir / "job.sh").string(), script);
  ::chmod((sub_dir / "job.sh").c_str(), 0755);
  // 3. sbatch, then its id
  const slurm::CommandResult r = commands_.run(args, 120);
  std::string array_id;
  if (r.rc == 0) {
    array_id = slurm::parse_sbatch_id(r.out);  // throws (submission left 'submitting') if unreadable
  } else {
    array_id = find_lost_submission(name);  // a timeout may still have submitted it
    if (array_id.empty()) {
      if (r.rc != -1) store_.submission_never_happened(sub, first_line(r.text()));
      throw std::runtime_error("sbatch failed: " + first_line(r.text()));
    }
  }
  // Fault injection for the tests: die exactly in the window this design exists for (Slurm has
  // the array, the database does not know its id yet).
  if (const char* fault = std::getenv("BEVERLOO_FAULT"); fault && std::string(fault) == "after_sbatch") ::_exit(86);
  store_.submission_done(sub, array_id);
  for (auto& [id, t] : tracked_)
    if (t.submission == sub) t.array_id = array_id;
  std::fprintf(stderr, "[beverloo] slurm: submitted %zu jobs as array %s (%d tasks, %s)\n", attempt_tasks.size(),
               array_id.c_str(), size, name.c_str());
  poll_interval_ = options_.poll_min_s;
  next_poll_ = steady_now() + poll_interval_;
}

std::string SlurmExecutor::find_lost_submission(const std::string& name) {
  const slurm::CommandResult q = commands_.run(
      {"squeue", "--noheader", "--array", "--states=all", "--name=" + name, std::string("--format=") + slurm::kSqueueFormat});
  if (q.rc == 0)
    for (const auto& r : slurm::parse_squeue(q.out))
      if (r.name == name) return r.array_job_id;
  if (have_sacct_) {
    const slurm::CommandResult a = commands_.run({"sacct", "-X", "-n", "-P", "--starttime=now-30days", "--name=" + name,
                                                  std::string("--format=") + slurm::kSacctFields});
    if (a.rc == 0)
      for (const auto& r : slurm::parse_sacct(a.out))
        if (r.name == name) return r.array_job_id;
  }
  if (!jobcomp_path_.empty())
    for (const auto& r : slurm::parse_jobcomp(job_files::read_text(jobcomp_path_)))
      if (r.name == name) return r.array_job_id;
  return "";
}

bool SlurmExecutor::adopt(const RunningAttempt& a) {
  if (a.submission < 0) return false;  // claimed, but the coordinator died before recording a submission
  SlurmSubmission sub = store_.submission(a.submission);
  if (sub.state == "submitting") {  // the coordinator died around sbatch: find out whether it ran
    const std::string id = find_lost_submission(sub.name);
    if (id.empty()) {
      store_.submission_never_happened(sub.id, "not found in Slurm by a restarted coordinator");
      sub.state = "never_submitted";
    } else {
      store_.submission_done(sub.id, id);
      sub.state = "submitted";
      sub.slurm_job_id = id;
    }
  }
  if (sub.state != "submitted") return false;
  submission_names_[sub.id] = sub.name;
  Tracked t;
  t.attempt_id = a.attempt_id;
  t.dir = (fs::path(dir_) / a.dir).string();
  t.token = a.token;
  t.submission = sub.id;
  t.array_id = sub.slurm_job_id;
  t.task = a.array_task;
  tracked_[a.attempt_id] = t;
  return true;
}

std::map<slurm::TaskKey, slurm::TaskRecord> SlurmExecutor::accounting(const std::set<std::string>& array_ids) {
  std::set<std::string> names;
  for (const auto& [id, n] : submission_names_) names.insert(n);
  std::vector<slurm::TaskRecord> records;
  if (have_sacct_) {
    std::string ids;
    for (const std::string& a : array_ids) ids += (ids.empty() ? "" : ",") + a;
    const slurm::CommandResult r =
        commands_.run({"sacct", "-X", "-n", "-P", "-D", "-j", ids, std::string("--format=") + slurm::kSacctFields});
    if (r.rc == 0) records = slurm::parse_sacct(r.out);
  } else if (!jobcomp_path_.empty()) {
    records = slurm::parse_jobcomp(job_files::read_text(jobcomp_path_));
  }
  std::vector<slurm::TaskRecord> ours;
  for (const auto& r : records)  // job ids are reused after a clean restart: the random name decides
    if (names.count(r.name) && array_ids.count(r.array_job_id)) ours.push_back(r);
  return slurm::by_task(ours);
}

void SlurmExecutor::observe_files(Tracked& t) {
  const auto hb = job_files::read_heartbeat(t.dir);
  if (!hb || hb->token != t.token || hb->unix_time <= t.last_heartbeat) return;
  t.last_heartbeat = hb->unix_time;
  store_.heartbeat_at(t.attempt_id, hb->unix_time);
  if (hb->slurm_restarts > t.restarts) {
    t.restarts = hb->slurm_restarts;
    store_.set_slurm_state(t.attempt_id, t.state.empty() ? "RUNNING" : t.state, t.restarts);
  }
}

std::string SlurmExecutor::scontrol_exit_code(const Tracked& t) {
  // squeue shows no exit code; a FAILED task's tells a SIGKILLed worker from a crash (verdict_for)
  const std::string task = t.array_id + "_" + std::to_string(t.task);
  const slurm::CommandResult r = commands_.run({"scontrol", "show", "job", "-o", task});
  if (r.rc != 0) return "";
  for (const slurm::TaskRecord& rec : slurm::parse_jobcomp(r.out))
    if (rec.array_job_id == t.array_id && rec.task == t.task) return rec.exit_code;
  return "";
}

WorkerExit SlurmExecutor::ended(const Tracked& t, const std::string& state, const std::string& exit_code, bool with_verdict) {
  WorkerExit e;
  e.attempt_id = t.attempt_id;
  if (with_verdict && !state.empty()) {
    const slurm::Verdict v = slurm::verdict_for(state, exit_code);
    e.verdict = v.cls;
    e.message = v.message + " [Slurm " + t.array_id + "_" + std::to_string(t.task) + "]";
  }
  return e;
}

std::vector<WorkerExit> SlurmExecutor::poll() {
  std::vector<WorkerExit> out;
  const double now = steady_now();
  if (now < next_poll_ || tracked_.empty()) return out;
  std::set<std::string> arrays;
  for (const auto& [id, t] : tracked_) arrays.insert(submission_names_[t.submission]);
  std::string names;
  for (const std::string& n : arrays) names += (names.empty() ? "" : ",") + n;
  const slurm::CommandResult q = commands_.run(
      {"squeue", "--noheader", "--array", "--states=all", "--name=" + names, std::string("--format=") + slurm::kSqueueFormat});
  if (q.rc != 0) {  // no answer is no information: conclude nothing, ask again later
    std::fprintf(stderr, "[beverloo] slurm: squeue failed (%s); retrying\n", first_line(q.text()).c_str());
    poll_interval_ = std::min(poll_interval_ * 2, options_.poll_max_s);
    next_poll_ = now + poll_interval_;
    return out;
  }
  const auto queue = slurm::by_task(slurm::parse_squeue(q.out));
  std::set<std::string> missing_arrays;
  for (const auto& [id, t] : tracked_)
    if (!slurm::find_task(queue, t.array_id, t.task)) missing_arrays.insert(t.array_id);
  const auto final_records = missing_arrays.empty() ? std::map<slurm::TaskKey, slurm::TaskRecord>{} : accounting(missing_arrays);

  bool changed = false;
  std::map<slurm::TaskKey, double> task_life;  // RUNNING tasks: last sign of life (unix seconds)
  std::vector<std::int64_t> done;
  for (auto& [id, t] : tracked_) {
    observe_files(t);
    const auto outcome = job_files::read_outcome(t.dir);
    const bool ours = outcome && outcome->token == t.token;
    const slurm::TaskKey key{t.array_id, t.task};
    const slurm::TaskRecord* rec = slurm::find_task(queue, t.array_id, t.task);
    if (!rec) rec = slurm::find_task(final_records, t.array_id, t.task);
    const bool known = rec != nullptr;
    if (known && rec->state != t.state) {
      t.state = rec->state;
      store_.set_slurm_state(t.attempt_id, t.state, t.restarts);
      changed = true;
    }
    if (known && !slurm::terminal(t.state)) {  // Slurm still owns it (queued, running, requeued, held)
      t.ended_since = -1;
      if (t.state == "RUNNING") {
        if (t.running_since < 0) t.running_since = unix_now();
        double& life = task_life[key];
        life = std::max({life, t.running_since, t.last_heartbeat});
      }
      if (ours && outcome->exit_code == 0) {  // a finished job of a bundle whose task still runs
        out.push_back(ended(t, "", "", false));
        done.push_back(id);
      }
      continue;
    }
    if (t.ended_since < 0) t.ended_since = now;
    const double waited = now - t.ended_since;
    // A result or a science failure is final. "interrupted" is not: a requeued task (scontrol
    // requeue, preemption with requeue) passes through ended-looking states and runs the same
    // attempt again, so it gets the grace period, as does a task that ended without files (NFS lag).
    const bool final_outcome = ours && outcome->failure_class != to_string(FailureClass::Interrupted);
    if (known) {
      if (final_outcome || waited >= options_.result_grace_s) {
        std::string exit_code = rec->exit_code;
        if (!final_outcome && t.state == "FAILED" && exit_code.empty()) exit_code = scontrol_exit_code(t);
        out.push_back(ended(t, t.state, exit_code, true));
        done.push_back(id);
      }
    } else if (final_outcome) {  // forgotten by squeue, no accounting record: the result file speaks for itself
      out.push_back(ended(t, "", "", false));
      done.push_back(id);
    } else if (waited >= std::max(options_.result_grace_s, 4 * options_.poll_max_s)) {
      WorkerExit e = ended(t, "", "", false);
      if (!ours) {
        e.verdict = FailureClass::Lost;
        e.message = "Slurm no longer knows task " + t.array_id + "_" + std::to_string(t.task) + " and it left no result";
      }
      out.push_back(e);
      done.push_back(id);
    }
  }
  for (std::int64_t id : done) tracked_.erase(id);
  // stalled: RUNNING, but no heartbeat for stall_timeout: cancel the task and rerun its attempts
  for (const auto& [key, life] : task_life) {
    const double silent = unix_now() - life;
    if (silent < options_.stall_timeout_s) continue;
    commands_.run({"scancel", key.first + "_" + std::to_string(key.second)});
    for (auto it = tracked_.begin(); it != tracked_.end();) {
      if (it->second.array_id != key.first || it->second.task != key.second) {
        ++it;
        continue;
      }
      WorkerExit e = ended(it->second, "", "", false);
      e.verdict = FailureClass::Stalled;
      e.message = "no heartbeat for " + std::to_string(static_cast<int>(silent)) + " s while RUNNING; cancelled (scancel " +
                  key.first + "_" + std::to_string(key.second) + ") and rerun from its checkpoint";
      out.push_back(e);
      it = tracked_.erase(it);
    }
  }
  if (changed || !out.empty())
    poll_interval_ = options_.poll_min_s;
  else
    poll_interval_ = std::min(poll_interval_ * 2, options_.poll_max_s);
  next_poll_ = now + poll_interval_;
  return out;
}

void SlurmExecutor::wait() {
  const double left = next_poll_ - steady_now();
  std::this_thread::sleep_for(std::chrono::duration<double>(std::clamp(left, 0.01, 0.2)));
}

std::vector<WorkerExit> SlurmExecutor::stop_all() {
  if (!tracked_.empty())
    std::fprintf(stderr, "[beverloo] slurm: %zu attempts stay with Slurm; the next `beverloo run` collects them\n",
                 tracked_.size());
  return {};
}

}  // namespace beverloo
