#pragma once
// SIGTERM, SIGINT and SIGHUP stop a run at the end of its current step (run/simulation.cpp), not
// in the middle of a write: the handler only records the signal.
#include <string>

#include "silodem/core/job_stop.hpp"

namespace silodem {

void install_stop_signals();
/// The signal that asked to stop, or 0.
int stop_signal();
/// For tests: as if `sig` had arrived (0 clears it).
void request_stop(int sig);
std::string signal_name(int sig);

/// The job stopped on a signal: exit code 128 + signal, as a shell reports a killed process.
class Interrupted : public JobStop {
 public:
  Interrupted(int sig, const std::string& message) : JobStop(128 + sig, message) {}
};

}  // namespace silodem
