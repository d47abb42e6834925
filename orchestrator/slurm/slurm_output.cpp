#include "slurm_output.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

namespace beverloo::slurm {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> data_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    line = trim(line);
    if (!line.empty() && line[0] != '#') out.push_back(line);
  }
  return out;
}

bool parse_int(const std::string& s, int& v) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return false;
  v = std::stoi(s);
  return true;
}

/// "221_3" -> ("221", {3}); "221_[7-9%2]" or "221_[1,4-5]" -> ("221", {7, 8, 9}); "221" -> ("221", {-1}).
std::pair<std::string, std::vector<int>> split_job_id(const std::string& id) {
  const auto us = id.find('_');
  if (us == std::string::npos) return {id, {-1}};
  const std::string array = id.substr(0, us);
  std::string rest = id.substr(us + 1);
  std::vector<int> tasks;
  int v = 0;
  if (parse_int(rest, v)) return {array, {v}};
  if (rest.size() > 2 && rest.front() == '[' && rest.back() == ']') {
    rest = rest.substr(1, rest.size() - 2);
    rest = rest.substr(0, rest.find('%'));
    for (const std::string& part : split(rest, ',')) {
      const auto dash = part.find('-');
      int a = 0, b = 0;
      if (dash == std::string::npos) {
        if (parse_int(part, a)) tasks.push_back(a);
      } else if (parse_int(part.substr(0, dash), a) && parse_int(part.substr(dash + 1), b)) {
        for (int t = a; t <= b; ++t) tasks.push_back(t);
      }
    }
  }
  return {array, tasks};
}

std::vector<TaskRecord> last_per_task(const std::vector<TaskRecord>& in) {
  std::vector<TaskRecord> out;
  std::map<TaskKey, std::size_t> where;
  for (const TaskRecord& r : in) {
    const TaskKey k{r.array_job_id, r.task};
    auto it = where.find(k);
    if (it == where.end()) {
      where[k] = out.size();
      out.push_back(r);
    } else {
      out[it->second] = r;
    }
  }
  return out;
}

}  // namespace

std::string base_state(const std::string& raw) {
  std::string s = trim(raw);
  const auto space = s.find(' ');
  if (space != std::string::npos) s = s.substr(0, space);
  while (!s.empty() && s.back() == '+') s.pop_back();
  return s;
}

bool in_flight(const std::string& state) {
  static const std::set<std::string> states = {"PENDING",   "RUNNING",      "CONFIGURING", "COMPLETING", "REQUEUED",
                                               "REQUEUE_FED", "REQUEUE_HOLD", "RESIZING",  "SUSPENDED",  "STOPPED",
                                               "SIGNALING", "STAGE_OUT",    "RESV_DEL_HOLD", "SPECIAL_EXIT"};
  return states.count(state) > 0;
}

bool terminal(const std::string& state) {
  static const std::set<std::string> states = {"COMPLETED", "FAILED",    "CANCELLED", "TIMEOUT", "PREEMPTED",
                                               "NODE_FAIL", "BOOT_FAIL", "DEADLINE",  "OUT_OF_MEMORY", "REVOKED"};
  return states.count(state) > 0;
}

std::vector<TaskRecord> parse_squeue(const std::string& text) {
  std::vector<TaskRecord> out;
  for (const std::string& line : data_lines(text)) {
    const std::vector<std::string> f = split(line, '|');
    if (f.size() < 6) continue;  // not ours (a warning line, say)
    TaskRecord r;
    r.array_job_id = f[0];
    if (!parse_int(f[1], r.task)) r.task = -1;  // "N/A": not an array element
    r.state = base_state(f[3]);
    r.reason = f[4];
    r.name = f[5];
    out.push_back(r);
  }
  return out;
}

std::vector<TaskRecord> parse_sacct(const std::string& text) {
  std::vector<TaskRecord> all;
  for (const std::string& line : data_lines(text)) {
    const std::vector<std::string> f = split(line, '|');
    if (f.size() < 4) continue;
    const auto [array, tasks] = split_job_id(f[0]);
    for (int t : tasks) all.push_back({array, t, base_state(f[2]), "", f[1], f[3]});
  }
  return last_per_task(all);
}

std::vector<TaskRecord> parse_jobcomp(const std::string& text) {
  std::vector<TaskRecord> all;
  for (const std::string& line : data_lines(text)) {
    std::map<std::string, std::string> kv;
    std::istringstream in(line);
    std::string word;
    while (in >> word) {
      const auto eq = word.find('=');
      if (eq != std::string::npos) kv[word.substr(0, eq)] = word.substr(eq + 1);
    }
    TaskRecord r;
    r.array_job_id = kv.count("ArrayJobId") ? kv["ArrayJobId"] : kv["JobId"];
    if (!parse_int(kv["ArrayTaskId"], r.task)) r.task = -1;
    if (r.array_job_id.empty() || r.array_job_id == "0") r.array_job_id = kv["JobId"];
    r.state = base_state(kv["JobState"]);
    r.name = kv["Name"];
    r.exit_code = kv["ExitCode"];
    if (!r.array_job_id.empty() && !r.state.empty()) all.push_back(r);
  }
  return last_per_task(all);
}

std::string parse_sbatch_id(const std::string& out) {
  const std::string first = trim(out.substr(0, out.find('\n')));
  const std::string id = first.substr(0, first.find(';'));
  int v = 0;
  if (!parse_int(id, v)) throw std::runtime_error("sbatch printed no job id: \"" + trim(out) + "\"");
  return id;
}

std::map<std::string, std::string> parse_config(const std::string& text) {
  std::map<std::string, std::string> out;
  for (const std::string& line : data_lines(text)) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) out[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  return out;
}

Verdict verdict_for(const std::string& state, const std::string& exit_code) {
  const std::string code = exit_code.empty() ? "" : " (exit code " + exit_code + ")";
  if (state == "COMPLETED")
    return {FailureClass::Lost, "Slurm task COMPLETED but left no result for this attempt" + code + "; rerun"};
  if (state == "TIMEOUT" || state == "DEADLINE")
    return {FailureClass::Timeout, "Slurm " + state + ": resumes from its checkpoint"};
  if (state == "PREEMPTED") return {FailureClass::Preempted, "preempted by Slurm: resumes from its checkpoint"};
  if (state == "NODE_FAIL" || state == "BOOT_FAIL")
    return {FailureClass::NodeFailure, "Slurm " + state + ": node lost; resumes from its checkpoint"};
  if (state == "OUT_OF_MEMORY")
    return {FailureClass::OutOfMemory, "Slurm OUT_OF_MEMORY: give more memory (--sbatch-arg=--mem=...)" + code};
  if (state == "CANCELLED")
    return {FailureClass::Cancelled, "cancelled in Slurm (scancel); not retried: `beverloo campaign retry --include-cancelled` brings it back"};
  if (state == "FAILED") {
    // "exit:signal" as Slurm reports it: a worker killed by SIGKILL (by hand, by a watchdog; the
    // cgroup's OOM killer ends as OUT_OF_MEMORY) is `killed`, as locally: a free rerun from its
    // checkpoint. Any other failure without a result (a crash) is `internal`, from the budget.
    int exit_status = 0, signal = 0;
    const auto colon = exit_code.find(':');
    if (colon != std::string::npos && parse_int(exit_code.substr(0, colon), exit_status) &&
        parse_int(exit_code.substr(colon + 1), signal) && (signal == 9 || exit_status == 128 + 9))
      return {FailureClass::Killed, "Slurm task killed by SIGKILL" + code + "; resumes from its checkpoint"};
    return {FailureClass::Internal, "Slurm task FAILED without a result" + code};
  }
  return {FailureClass::Lost, "Slurm task ended as " + state + code};
}

std::map<TaskKey, TaskRecord> by_task(const std::vector<TaskRecord>& records) {
  std::map<TaskKey, TaskRecord> out;
  for (const TaskRecord& r : records) out[{r.array_job_id, r.task}] = r;
  return out;
}

const TaskRecord* find_task(const std::map<TaskKey, TaskRecord>& records, const std::string& array, int task) {
  if (auto it = records.find({array, task}); it != records.end()) return &it->second;
  if (auto meta = records.find({array, -1}); meta != records.end()) return &meta->second;
  return nullptr;
}

}  // namespace beverloo::slurm
