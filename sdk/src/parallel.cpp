#include "facet/parallel.hpp"

#include <algorithm>

#include "facet/context.hpp"

namespace facet {

ChunkPlan::ChunkPlan(std::int64_t count, std::int64_t min_chunk, int chunks)
    : count_(std::max<std::int64_t>(count, 0)) {
  const std::int64_t by_size = count_ / std::max<std::int64_t>(min_chunk, 1);
  chunks_ =
      static_cast<std::size_t>(std::max<std::int64_t>(std::min<std::int64_t>(by_size, chunks), 1));
}

std::int64_t ChunkPlan::chunk_begin(std::size_t i) const {
  // Even shares, the remainder spread over the first ranges.
  const auto n = static_cast<std::int64_t>(chunks_);
  const auto k = static_cast<std::int64_t>(std::min(i, chunks_));
  return k * (count_ / n) + std::min(k, count_ % n);
}

void parallel_for(ParallelRunner* runner, std::int64_t count, std::int64_t min_chunk,
                  const std::function<void(std::int64_t begin, std::int64_t end)>& body) {
  if (count <= 0) return;
  // A few more ranges than threads, so that a worker that joins late still finds work.
  constexpr int kRangesPerThread = 4;
  const int threads = runner != nullptr ? runner->concurrency() : 1;
  const ChunkPlan plan(count, min_chunk, threads > 1 ? threads * kRangesPerThread : 1);
  if (plan.size() <= 1) {
    body(0, count);
    return;
  }
  runner->run(plan.size(),
              [&](std::size_t i) { body(plan.chunk_begin(i), plan.chunk_begin(i + 1)); });
}

void ProcessContext::parallel_for(
    std::int64_t count, std::int64_t min_chunk,
    const std::function<void(std::int64_t begin, std::int64_t end)>& body) const {
  facet::parallel_for(runner_, count, min_chunk, body);
}

}  // namespace facet
