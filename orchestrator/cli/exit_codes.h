#pragma once
/// \file exit_codes.h
/// \brief The exit codes of every beverloo command (documented in docs/cli.md).
namespace beverloo::exit_code {
inline constexpr int kOk = 0;           ///< finished (a clogged run is a finished run)
inline constexpr int kInternal = 1;     ///< a bug: unexpected exception
inline constexpr int kConfig = 2;       ///< bad input: names the field and the reason; nothing written
inline constexpr int kUnstable = 3;     ///< the simulation became unphysical (NaN, escape, overlap)
inline constexpr int kIo = 4;           ///< reading or writing files failed
inline constexpr int kInterrupted = 5;  ///< stopped by SIGINT/SIGTERM/SIGUSR1 after writing a checkpoint
inline constexpr int kBusy = 6;         ///< another coordinator holds the campaign
inline constexpr int kJobsFailed = 7;   ///< the campaign finished, but some jobs failed for good
}  // namespace beverloo::exit_code
