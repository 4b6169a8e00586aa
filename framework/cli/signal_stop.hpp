#pragma once
// Ctrl-C (SIGINT) and SIGTERM end a run the way the end of its input does: the frames already
// begun are finished and written whole, the stages are closed (a recording is completed), the
// statistics and the trace are written, and the process exits with 128 + the signal's number.

#include <atomic>
#include <csignal>

namespace facet::cli {

// While one exists, SIGINT and SIGTERM set stop() instead of ending the process; a second signal
// ends it at once (for a stage that hangs). A SIGINT that was ignored when facet started (a
// command started in the background by a shell) stays ignored. One at a time per process.
class SignalStop {
 public:
  SignalStop();
  ~SignalStop();
  SignalStop(const SignalStop&) = delete;
  SignalStop& operator=(const SignalStop&) = delete;

  // For RunOptions::stop.
  const std::atomic<bool>& stop() const;
  // The signal that set stop(), or 0.
  int signal() const;

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

// "SIGINT", "SIGTERM" or "signal N".
const char* signal_name(int signal);

}  // namespace facet::cli
