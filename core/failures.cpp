#include "failures.h"

#include <array>

namespace beverloo {
namespace {
using R = RetryPolicy;
using F = FailureClass;
constexpr std::array<FailureInfo, 14> kTable = {{
    {F::InvalidParameters, "invalid_parameters", exit_code::kConfig, "failed", R::Never},
    // The engine is deterministic: a retry resumes the same checkpoint with the same binary and
    // blows up at the same step, bit for bit, so it would only spend CPU (Fig. 6's steep funnels:
    // 5 jobs x 3 attempts). `campaign retry` runs such jobs again, e.g. after an engine change.
    {F::BlowUp, "blow_up", exit_code::kUnstable, "failed", R::Never},
    {F::Killed, "killed", -1, "failed", R::Free},
    {F::Timeout, "timeout", -1, "failed", R::Free},
    {F::Io, "io", exit_code::kIo, "failed", R::Budgeted},
    {F::Interrupted, "interrupted", exit_code::kInterrupted, "interrupted", R::Free},
    {F::Lost, "lost", exit_code::kLockBusy, "lost", R::Free},
    {F::Internal, "internal", exit_code::kInternal, "failed", R::Budgeted},
    // an "io" failure the coordinator finds was for want of room: the job waits, its budget untouched
    {F::DiskFull, "disk_full", -1, "failed", R::Free},
    {F::Cancelled, "cancelled", -1, "cancelled", R::Cancel},
    {F::Preempted, "preempted", -1, "interrupted", R::Free},
    {F::NodeFailure, "node_failure", -1, "lost", R::Free},
    {F::OutOfMemory, "out_of_memory", exit_code::kOutOfMemory, "failed", R::Budgeted},
    {F::Stalled, "stalled", -1, "lost", R::Free},
}};
}  // namespace

const FailureInfo& failure_info(FailureClass c) {
  for (const FailureInfo& f : kTable)
    if (f.cls == c) return f;
  return kTable[7];  // Internal; unreachable while the table lists every class
}

std::optional<FailureClass> failure_from_name(std::string_view name) {
  for (const FailureInfo& f : kTable)
    if (f.name == name) return f.cls;
  return std::nullopt;
}

FailureClass failure_from_exit(bool signaled, int code) {
  if (signaled) return FailureClass::Killed;
  for (const FailureInfo& f : kTable)
    if (f.exit_code == code && code != exit_code::kInternal) return f.cls;
  return FailureClass::Internal;
}

}  // namespace beverloo
