#include "signal_stop.hpp"

#include <csignal>
#include <cstdlib>

namespace facet::cli {
namespace {

// A signal handler can reach nothing but objects of static storage duration, so these two are
// the process's only mutable globals; lock-free atomics are safe to touch from a handler.
std::atomic<bool> stop_flag{false};
std::atomic<int> stop_signal{0};

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int signal) {
  if (stop_flag.load()) std::_Exit(128 + signal);  // the second one: no more waiting
  stop_signal.store(signal);
  stop_flag.store(true);
}

}  // namespace

SignalStop::SignalStop() {
  stop_flag.store(false);
  stop_signal.store(0);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, nullptr, &previous_int_);
  if (previous_int_.sa_handler != SIG_IGN) sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, &previous_term_);
}

SignalStop::~SignalStop() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

const std::atomic<bool>& SignalStop::stop() const {
  return stop_flag;
}

int SignalStop::signal() const {
  return stop_signal.load();
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

}  // namespace facet::cli
