#pragma once
// A ParallelRunner for tests of stages that use parallel_for: it claims `threads` threads, so
// work is split as on a machine with that many, but runs the ranges last to first on the calling
// thread. A stage whose result depends on how its range was split or in which order the pieces
// ran gives another result under it than inline.

#include <cstddef>
#include <functional>

#include "facet/parallel.hpp"

namespace facet::testing {

class ReverseRunner final : public ParallelRunner {
 public:
  explicit ReverseRunner(int threads) : threads_(threads) {}
  int concurrency() const override { return threads_; }
  void run(std::size_t chunks, const std::function<void(std::size_t)>& chunk) override {
    ++runs_;
    for (std::size_t i = chunks; i-- > 0;)
      chunk(i);
  }
  // How many parallel_for calls were split (not run inline).
  int runs() const { return runs_; }

 private:
  int threads_;
  int runs_ = 0;
};

}  // namespace facet::testing
