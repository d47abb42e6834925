#pragma once
/// \file child_process.h
/// \brief Runs another program without a shell: the arguments go to exec as they are, so no
/// text (a path, a name) is ever read as a command. Its output is captured, its time limited.
/// Used for gnuplot (the report's figures) and Slurm's command-line tools.
#include <string>
#include <vector>

namespace beverloo {

struct ChildResult {
  int rc = -1;             ///< exit status; -1 if it could not start, was killed or timed out
  bool timed_out = false;  ///< killed at the time limit
  std::string out, err;    ///< its standard output and error (err also says why it could not start)
  std::string text() const { return out + err; }
};

/// Runs argv[0] (looked up in PATH) with standard input from /dev/null, in directory cwd (the
/// caller's if empty), killed (SIGKILL) when it runs past timeout_s seconds.
ChildResult run_child(const std::vector<std::string>& argv, double timeout_s, const std::string& cwd = "");

}  // namespace beverloo
