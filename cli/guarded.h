#pragma once
/// \file guarded.h
/// \brief How every campaign-level command ends: each kind of error becomes its message on
/// stderr ("beverloo CMD: ...") and its exit code (docs/cli.md), never an exception.
#include <new>
#include <cstdio>
#include <filesystem>

#include "core/errors.h"
#include "core/failures.h"
#include "core/text_escape.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "orchestrator/db/database.h"
#include "orchestrator/sweep/sweep.h"

namespace beverloo {

/// Runs a command body, turning every error into its message and exit code.
template <class F>
inline int guarded(const char* cmd, F&& body) {
  try {
    return body();
  } catch (const SweepError& e) {
    std::fprintf(stderr, "beverloo %s: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kConfig;
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "beverloo %s: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kConfig;
  } catch (const MissingCampaign& e) {
    std::fprintf(stderr, "beverloo %s: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kConfig;
  } catch (const CampaignBusy& e) {
    std::fprintf(stderr, "beverloo %s: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kBusy;
  } catch (const db::DbError& e) {
    std::fprintf(stderr, "beverloo %s: database: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kIo;
  } catch (const IoError& e) {
    std::fprintf(stderr, "beverloo %s: I/O error: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kIo;
  } catch (const std::filesystem::filesystem_error& e) {  // a name too long, a loop of links, a file for a directory
    std::fprintf(stderr, "beverloo %s: I/O error: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kIo;
  } catch (const std::bad_alloc&) {  // never an abort: the limit is the machine's or the process's
    std::fprintf(stderr, "beverloo %s: out of memory: an allocation failed (the machine's memory, or this process's limit: "
                         "ulimit -v, a cgroup's memory.max, Slurm's --mem); nothing more was written\n", cmd);
    return exit_code::kOutOfMemory;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beverloo %s: internal error: %s\n", cmd, terminal_safe(e.what()).c_str());
    return exit_code::kInternal;
  }
}

}  // namespace beverloo
