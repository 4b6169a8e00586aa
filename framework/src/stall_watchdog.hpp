#pragma once
// Watches the stage calls in progress and reports, once per call, one that has been running for
// longer than a threshold: which node holds which frame, and for how long. A hung stage then
// tells the user where it hangs instead of the run silently stopping.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

#include "facet/framework/executor.hpp"
#include "node_runtime.hpp"

namespace facet::detail {

class StallWatchdog {
 public:
  // `threads` calls may be in progress at once, one per executor thread. Inactive (no thread of
  // its own) when `after` is zero or there is no one to tell.
  StallWatchdog(std::chrono::milliseconds after, std::function<void(const StallReport&)> on_stall,
                int threads);
  ~StallWatchdog();
  StallWatchdog(const StallWatchdog&) = delete;
  StallWatchdog& operator=(const StallWatchdog&) = delete;

  void begin(int thread, const ValidatedNode& node, std::int64_t frame, Clock::time_point start);
  void end(int thread);

 private:
  struct Call {
    const ValidatedNode* node = nullptr;  // nullptr: the thread is not in a stage call
    std::int64_t frame = 0;
    Clock::time_point start;
    bool reported = false;
  };

  void watch(const std::stop_token& stop);

  std::chrono::milliseconds after_;
  std::function<void(const StallReport&)> on_stall_;
  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::vector<Call> calls_;
  std::jthread thread_;  // last: started after, and joined before, the members it reads
};

}  // namespace facet::detail
