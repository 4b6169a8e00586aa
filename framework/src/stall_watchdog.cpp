#include "stall_watchdog.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace facet::detail {

StallWatchdog::StallWatchdog(std::chrono::milliseconds after,
                             std::function<void(const StallReport&)> on_stall, int threads)
    : after_(after), on_stall_(std::move(on_stall)), calls_(static_cast<std::size_t>(threads)) {
  if (after_.count() > 0 && on_stall_) {
    thread_ = std::jthread([this](const std::stop_token& stop) { watch(stop); });
  }
}

StallWatchdog::~StallWatchdog() {
  if (!thread_.joinable()) return;
  thread_.request_stop();
  wake_.notify_all();
}

void StallWatchdog::begin(int thread, const ValidatedNode& node, std::int64_t frame,
                          Clock::time_point start) {
  if (!thread_.joinable()) return;
  const std::lock_guard lock(mutex_);
  calls_[static_cast<std::size_t>(thread)] = Call{&node, frame, start, false};
}

void StallWatchdog::end(int thread) {
  if (!thread_.joinable()) return;
  const std::lock_guard lock(mutex_);
  calls_[static_cast<std::size_t>(thread)].node = nullptr;
}

void StallWatchdog::watch(const std::stop_token& stop) {
  // A quarter of the threshold between looks: a stall is reported at most 25 % late, and the
  // watchdog costs nothing measurable when nothing stalls.
  const auto period =
      std::clamp(after_ / 4, std::chrono::milliseconds(1), std::chrono::milliseconds(250));
  std::unique_lock lock(mutex_);
  while (!stop.stop_requested()) {
    wake_.wait_for(lock, stop, period, [] { return false; });
    if (stop.stop_requested()) break;
    std::vector<StallReport> reports;
    const auto now = Clock::now();
    for (auto& call : calls_) {
      if (call.node == nullptr || call.reported || now - call.start < after_) continue;
      call.reported = true;
      const double held_ms = ms_between(call.start, now);
      reports.push_back({call.node->id, call.node->stage->spec.name(), call.frame, held_ms,
                         fmt::format("{} has held frame {} for {:.0f} ms (stall threshold {} ms)",
                                     describe(*call.node), call.frame, held_ms, after_.count())});
    }
    // Reported without the lock, so that a slow handler never delays the executor's threads.
    lock.unlock();
    for (const auto& report : reports)
      on_stall_(report);
    lock.lock();
  }
}

}  // namespace facet::detail
