#pragma once
// Parallelism inside one stage call, on the executor's workers.
//
// Stages never start threads of their own. A stage that can split its work (rows of an image,
// objects of a frame) calls ProcessContext::parallel_for(), and the executor lends it the
// workers of its pool that are idle at that moment; the calling thread always takes part, so a
// call makes progress when every other worker is busy with other frames, and with one thread
// (`--threads 1`, StageRunner, the sequential executor) the body simply runs inline.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace facet {

// What an executor implements to lend its workers. run() calls chunk(i) once for every i in
// [0, chunks), on the calling thread and on any idle worker, and returns when all calls have
// returned. If calls throw, the remaining chunks are not started and the first exception is
// rethrown on the calling thread.
class ParallelRunner {
 public:
  virtual ~ParallelRunner() = default;
  // Threads that may run chunks at once, the caller included (1 = no help to be had).
  virtual int concurrency() const = 0;
  virtual void run(std::size_t chunks, const std::function<void(std::size_t)>& chunk) = 0;
};

// ProcessContext::parallel_for() for code that has no context (an algorithm a stage calls, a
// benchmark): runner may be nullptr, which runs body(0, count) inline.
void parallel_for(ParallelRunner* runner, std::int64_t count, std::int64_t min_chunk,
                  const std::function<void(std::int64_t begin, std::int64_t end)>& body);

// Splits [0, count) into at most `chunks` contiguous ranges of at least `min_chunk` items (at
// least one range; sizes differ by at most one, the larger ones first). size() is how many
// ranges there are; range i is [chunk_begin(i), chunk_begin(i + 1)).
struct ChunkPlan {
  ChunkPlan(std::int64_t count, std::int64_t min_chunk, int chunks);
  std::int64_t chunk_begin(std::size_t i) const;
  std::size_t size() const { return chunks_; }

 private:
  std::int64_t count_;
  std::size_t chunks_;
};

// Working memory for the bodies of a parallel_for() that run at the same time: each body
// leases one T, kept between calls so that a stage allocates it once, not once per frame.
//   auto buffers = pool.lease();   // a T no other body holds; given back when `buffers` goes
template <class T>
class WorkspacePool {
 public:
  class Lease {
   public:
    Lease(WorkspacePool& pool, std::unique_ptr<T> value) : pool_(&pool), value_(std::move(value)) {}
    Lease(Lease&&) noexcept = default;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (value_) pool_->give_back(std::move(value_));
    }
    T& operator*() const { return *value_; }
    T* operator->() const { return value_.get(); }

   private:
    WorkspacePool* pool_;
    std::unique_ptr<T> value_;
  };

  Lease lease() {
    const std::lock_guard lock(mutex_);
    if (free_.empty()) return Lease(*this, std::make_unique<T>());
    std::unique_ptr<T> value = std::move(free_.back());
    free_.pop_back();
    return Lease(*this, std::move(value));
  }

 private:
  void give_back(std::unique_ptr<T> value) {
    const std::lock_guard lock(mutex_);
    free_.push_back(std::move(value));
  }

  std::mutex mutex_;
  std::vector<std::unique_ptr<T>> free_;
};

}  // namespace facet
