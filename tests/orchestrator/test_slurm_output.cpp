// Reading Slurm's output: recorded outputs of Slurm 22.05.8 (tests/data/slurm/*_recorded.txt)
// and outputs in the same format for the states this one-node cluster cannot provoke
// (*_constructed.txt: PREEMPTED, NODE_FAIL, OUT_OF_MEMORY, ...). Also the reconciliation table
// and the bundling of jobs into array tasks.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "orchestrator/executors/slurm_executor.h"
#include "orchestrator/slurm/slurm_output.h"

namespace beverloo::slurm {
namespace {

std::string data(const std::string& name) {
  std::ifstream in(std::string(BEVERLOO_TEST_DATA_DIR) + "/slurm/" + name);
  EXPECT_TRUE(in.good()) << name;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(SlurmOutput, SqueueRecordedLinesAreReadTaskByTask) {
  const auto r = parse_squeue(data("squeue_recorded.txt"));
  ASSERT_EQ(r.size(), 6u);
  EXPECT_EQ(r[0].array_job_id, "1");
  EXPECT_EQ(r[0].task, 1);
  EXPECT_EQ(r[0].state, "FAILED");
  EXPECT_EQ(r[0].reason, "NonZeroExitCode");
  EXPECT_EQ(r[0].name, "beverloo-rec1");
  EXPECT_EQ(r[1].state, "PENDING");
  EXPECT_EQ(r[1].reason, "JobArrayTaskLimit");  // held back by the %2 throttle
  // by_task keeps the newest line of a task: task 2 was cancelled, task 0 requeued
  const auto m = by_task(r);
  EXPECT_EQ(m.at({"1", 2}).state, "CANCELLED");
  EXPECT_EQ(m.at({"1", 0}).state, "PENDING");
  EXPECT_EQ(m.at({"1", 0}).reason, "BeginTime");
  const auto end = by_task(parse_squeue(data("squeue_recorded_end.txt")));
  EXPECT_EQ(end.size(), 4u);
  EXPECT_EQ(end.at({"1", 0}).state, "COMPLETED");
  EXPECT_EQ(end.at({"1", 1}).state, "FAILED");
}

TEST(SlurmOutput, SqueueConstructedStatesAndForeignJobs) {
  const auto m = by_task(parse_squeue(data("squeue_constructed.txt")));
  EXPECT_EQ(m.at({"77", 0}).state, "PREEMPTED");
  EXPECT_EQ(m.at({"77", 1}).state, "NODE_FAIL");
  EXPECT_EQ(m.at({"77", 2}).state, "OUT_OF_MEMORY");
  EXPECT_EQ(m.at({"78", -1}).state, "RUNNING");  // %K is N/A for a job that is not an array element
  for (const char* s : {"PREEMPTED", "NODE_FAIL", "OUT_OF_MEMORY", "TIMEOUT", "BOOT_FAIL", "DEADLINE"}) {
    EXPECT_TRUE(terminal(s)) << s;
    EXPECT_FALSE(in_flight(s)) << s;
  }
  for (const char* s : {"PENDING", "RUNNING", "REQUEUE_HOLD", "COMPLETING", "SUSPENDED", "REQUEUED", "CONFIGURING"}) {
    EXPECT_TRUE(in_flight(s)) << s;
    EXPECT_FALSE(terminal(s)) << s;
  }
}

TEST(SlurmOutput, SacctLastRecordPerTaskWinsAndPendingRangesExpand) {
  const auto m = by_task(parse_sacct(data("sacct_constructed.txt")));
  EXPECT_EQ(m.at({"221", 1}).state, "COMPLETED");  // REQUEUED, PREEMPTED, then COMPLETED (-D)
  EXPECT_EQ(m.at({"221", 2}).state, "CANCELLED");  // "CANCELLED by 0"
  EXPECT_EQ(m.at({"221", 3}).exit_code, "7:0");
  EXPECT_EQ(m.at({"221", 5}).state, "OUT_OF_MEMORY");
  for (int t : {7, 8, 9}) EXPECT_EQ(m.at({"221", t}).state, "PENDING") << t;  // 221_[7-9%2]
  EXPECT_EQ(m.count({"221", 10}), 0u);
  EXPECT_EQ(base_state("CANCELLED+"), "CANCELLED");
}

TEST(SlurmOutput, JobcompRecordedRequeueRecordIsSupersededByTheFinalOne) {
  const auto m = by_task(parse_jobcomp(data("jobcomp_recorded.txt")));
  EXPECT_EQ(m.at({"1", 1}).state, "FAILED");
  EXPECT_EQ(m.at({"1", 1}).exit_code, "7:0");
  EXPECT_EQ(m.at({"1", 2}).state, "CANCELLED");
  EXPECT_EQ(m.at({"1", 0}).state, "COMPLETED");  // after its PENDING (requeue) record
  EXPECT_EQ(m.at({"1", 0}).name, "beverloo-rec1");
}

TEST(SlurmOutput, PendingTasksOfACancelledArrayAreFoundThroughItsMetaRecord) {
  // recorded: 12 tasks, throttle 2, scancel -u root while tasks 4-11 were pending
  const auto q = by_task(parse_squeue(data("squeue_recorded_cancelled_pending.txt")));
  ASSERT_NE(find_task(q, "1157", 7), nullptr);
  EXPECT_EQ(find_task(q, "1157", 7)->state, "CANCELLED");
  EXPECT_EQ(find_task(q, "1157", 3)->state, "CANCELLED");
  EXPECT_EQ(find_task(q, "1158", 0), nullptr);
  const auto j = by_task(parse_jobcomp(data("jobcomp_recorded_cancelled_pending.txt")));
  EXPECT_EQ(find_task(j, "1157", 0)->state, "COMPLETED");  // its own record
  EXPECT_EQ(find_task(j, "1157", 9)->state, "CANCELLED");  // the meta record: no ArrayTaskId
}

TEST(SlurmOutput, ScontrolShowJobGivesTheExitCode) {
  // `scontrol show job -o 970_1` as Slurm 22.05 printed it for a SIGKILLed worker (abridged)
  const std::string line =
      "JobId=972 ArrayJobId=970 ArrayTaskId=1 JobName=beverloo-0123456789abcdef UserId=root(0) Priority=1 "
      "JobState=FAILED Reason=NonZeroExitCode Dependency=(null) Requeue=1 Restarts=0 BatchFlag=1 Reboot=0 "
      "ExitCode=0:9 RunTime=00:00:03 TimeLimit=UNLIMITED\n";
  const auto records = parse_jobcomp(line);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].array_job_id, "970");
  EXPECT_EQ(records[0].task, 1);
  EXPECT_EQ(records[0].state, "FAILED");
  EXPECT_EQ(records[0].exit_code, "0:9");
}

TEST(SlurmOutput, SbatchAndConfig) {
  EXPECT_EQ(parse_sbatch_id("41\n"), "41");
  EXPECT_EQ(parse_sbatch_id("1234;cluster2\n"), "1234");
  EXPECT_THROW(parse_sbatch_id("sbatch: error: Batch job submission failed: Invalid partition name specified\n"),
               std::runtime_error);
  const auto c = parse_config("Configuration data as of 2026-11-22T08:59:00\nMaxArraySize            = 1001\n"
                              "JobCompType             = jobcomp/filetxt\nAccountingStorageType   = accounting_storage/none\n");
  EXPECT_EQ(c.at("MaxArraySize"), "1001");
  EXPECT_EQ(c.at("JobCompType"), "jobcomp/filetxt");
}

TEST(SlurmReconciliation, EveryEndMapsToTheTableOfOrchestrationPeers) {
  EXPECT_EQ(verdict_for("COMPLETED").cls, FailureClass::Lost);  // no result: a free rerun
  EXPECT_EQ(verdict_for("FAILED", "1:0").cls, FailureClass::Internal);
  // a worker SIGKILLed (the batch script execs it, so its signal is the task's): a free rerun
  // from its checkpoint, as locally; a crash (SIGSEGV) or an unknown code stays internal
  EXPECT_EQ(verdict_for("FAILED", "0:9").cls, FailureClass::Killed);
  EXPECT_EQ(verdict_for("FAILED", "137:0").cls, FailureClass::Killed);
  EXPECT_EQ(verdict_for("FAILED", "0:11").cls, FailureClass::Internal);
  EXPECT_EQ(verdict_for("FAILED", "").cls, FailureClass::Internal);
  EXPECT_EQ(verdict_for("FAILED", "garbage").cls, FailureClass::Internal);
  EXPECT_EQ(verdict_for("TIMEOUT").cls, FailureClass::Timeout);
  EXPECT_EQ(verdict_for("DEADLINE").cls, FailureClass::Timeout);
  EXPECT_EQ(verdict_for("PREEMPTED").cls, FailureClass::Preempted);
  EXPECT_EQ(verdict_for("NODE_FAIL").cls, FailureClass::NodeFailure);
  EXPECT_EQ(verdict_for("BOOT_FAIL").cls, FailureClass::NodeFailure);
  EXPECT_EQ(verdict_for("OUT_OF_MEMORY").cls, FailureClass::OutOfMemory);
  EXPECT_EQ(verdict_for("CANCELLED").cls, FailureClass::Cancelled);
  // resume without using the retry budget: time limits, preemption, lost nodes, stalls
  for (FailureClass c : {FailureClass::Timeout, FailureClass::Preempted, FailureClass::NodeFailure, FailureClass::Stalled,
                         FailureClass::Lost})
    EXPECT_TRUE(is_infrastructure(c)) << to_string(c);
  // the same memory request would fail again; a cancel is the user's decision
  for (FailureClass c : {FailureClass::OutOfMemory, FailureClass::Cancelled, FailureClass::Internal})
    EXPECT_FALSE(is_infrastructure(c)) << to_string(c);
  EXPECT_NE(verdict_for("OUT_OF_MEMORY", "0:125").message.find("--mem"), std::string::npos);
}

TEST(SlurmBundling, FixedSizeOrPackedByEstimatedCost) {
  const auto fixed = SlurmExecutor::bundle_jobs(std::vector<double>(7, 1.0), 3, 600);
  ASSERT_EQ(fixed.size(), 3u);
  EXPECT_EQ(fixed[2].size(), 1u);
  // packed: cheap jobs share a task up to the target, an expensive one gets its own
  const auto packed = SlurmExecutor::bundle_jobs({100, 200, 250, 5000, 50, 60}, 0, 600);
  ASSERT_EQ(packed.size(), 3u);
  EXPECT_EQ(packed[0], (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(packed[1], (std::vector<std::size_t>{3}));
  EXPECT_EQ(packed[2], (std::vector<std::size_t>{4, 5}));
  // 1000 one-minute jobs at a 10-minute target: 100 tasks of 10
  const auto thousand = SlurmExecutor::bundle_jobs(std::vector<double>(1000, 60.0), 0, 600);
  EXPECT_EQ(thousand.size(), 100u);
}

TEST(SlurmBundling, CostEstimateScalesWithParticlesAndTime) {
  const std::string small = R"({"N": 100, "w": 4, "zeta": 0.1, "mu": 1, "run": {"t_max": 100}})";
  const std::string big = R"({"N": 1600, "w": 4, "zeta": 0.1, "mu": 1, "run": {"t_max": 1000}})";
  const double a = SlurmExecutor::estimated_seconds(small), b = SlurmExecutor::estimated_seconds(big);
  EXPECT_GT(a, 0);
  EXPECT_NEAR(b / a, 160, 1e-9);
  EXPECT_TRUE(std::isinf(SlurmExecutor::estimated_seconds(R"({"N": "many"})")));
}

}  // namespace
}  // namespace beverloo::slurm
