#pragma once
/// \file stop_signal.h
/// \brief SIGINT, SIGTERM and SIGUSR1 ask a running simulation to checkpoint and stop.
#include <atomic>

namespace beverloo {
/// Installs the handlers; returns the flag they set.
const std::atomic<bool>* install_stop_handlers();
}  // namespace beverloo
