#pragma once
/// \file stop_signal.h
/// \brief SIGINT, SIGTERM and SIGUSR1 ask a running simulation to checkpoint and stop.
#include <csignal>

#include <atomic>

namespace beverloo {
/// The three stop signals as a set (a local worker starts with them blocked: see below).
sigset_t stop_signal_set();
/// Installs the handlers, then unblocks the three signals: a stop that arrived while they were
/// blocked (a local executor starts its workers so, and a stop sent before the handlers were
/// in place would otherwise kill the worker outright) is delivered to the handler now. Returns
/// the flag they set.
const std::atomic<bool>* install_stop_handlers();
}  // namespace beverloo
