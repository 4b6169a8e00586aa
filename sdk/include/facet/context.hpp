#pragma once
// ProcessContext: what a stage sees of one frame — its inputs, its outputs, metrics, warnings.
//
// The executor owns the slots and reuses one context per node, so a call costs no allocation
// beyond the packets a stage creates. Ports are looked up by name in the stage's (short) port
// list; a name that the stage did not declare is a programming error and throws.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/packet.hpp"
#include "facet/parallel.hpp"
#include "facet/stage_spec.hpp"

namespace facet {

struct Metric {
  std::string name;
  double value;
};

class ProcessContext {
 public:
  ProcessContext(const StageSpec& spec, std::string node_id);

  // --- inputs ---
  bool has_input(std::string_view port) const { return !input_packet(port).empty(); }
  const Packet& input_packet(std::string_view port) const;

  // The input's value; throws StageError when it is missing or of another type.
  template <class T>
  const T& input(std::string_view port) const {
    const T* value = input_packet(port).get_if<T>();
    if (value == nullptr) throw_bad_input(port, type_key<T>());
    return *value;
  }
  template <class T>
  std::shared_ptr<const T> input_shared(std::string_view port) const {
    auto value = input_packet(port).shared_as<T>();
    if (value == nullptr) throw_bad_input(port, type_key<T>());
    return value;
  }

  // --- outputs ---
  template <class T>
  void output(std::string_view port, T value) {
    output_packet(port, Packet::make<T>(std::move(value)));
  }
  // Forwards an existing packet (e.g. an input) without copying its payload.
  void output_packet(std::string_view port, Packet packet);

  // --- reporting ---
  // A named number for this frame ("valid_ratio", "segments"); aggregated by run and compare.
  void metric(std::string_view name, double value) {
    metrics_.push_back({std::string(name), value});
  }
  // A message for the user; the executor prints it with node id and frame.
  void warn(std::string message) { warnings_.push_back(std::move(message)); }

  // Sources only: there are no more frames. Outputs set in the same call are discarded.
  void end_of_stream() { end_of_stream_ = true; }

  // --- parallelism (facet/parallel.hpp) ---
  // Calls body(begin, end) over contiguous ranges that together cover [0, count) exactly once,
  // each of at least `min_chunk` items (unless count is smaller), on the executor's idle
  // workers and this thread; returns when all are done. Ranges run in any order and at the same
  // time, so a body writes only what belongs to its range (rows of an output image, entries of
  // a pre-sized vector) and the result must not depend on how the range was split. The first
  // exception a body throws is rethrown here.
  void parallel_for(std::int64_t count, std::int64_t min_chunk,
                    const std::function<void(std::int64_t begin, std::int64_t end)>& body) const;
  // Threads parallel_for() may use at once, this one included.
  int parallelism() const { return runner_ != nullptr ? runner_->concurrency() : 1; }
  // The workers themselves, for algorithms that take them (facet::parallel_for); may be null.
  ParallelRunner* parallel_runner() const { return runner_; }

  // --- frame ---
  std::int64_t frame_index() const { return frame_index_; }
  const std::string& node_id() const { return node_id_; }
  const StageSpec& spec() const { return *spec_; }

  // --- executor side ---
  void begin_frame(std::int64_t frame_index);
  std::span<Packet> inputs() { return inputs_; }
  std::span<Packet> outputs() { return outputs_; }
  std::span<const Packet> outputs() const { return outputs_; }
  const std::vector<Metric>& metrics() const { return metrics_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  bool at_end_of_stream() const { return end_of_stream_; }
  // The workers parallel_for() borrows; nullptr (the default) runs bodies inline.
  void set_parallel_runner(ParallelRunner* runner) { runner_ = runner; }

 private:
  [[noreturn]] void throw_bad_input(std::string_view port, std::string_view expected) const;
  std::size_t output_index(std::string_view port) const;

  const StageSpec* spec_;
  std::string node_id_;
  std::vector<Packet> inputs_;
  std::vector<Packet> outputs_;
  std::vector<Metric> metrics_;
  std::vector<std::string> warnings_;
  std::int64_t frame_index_ = 0;
  bool end_of_stream_ = false;
  ParallelRunner* runner_ = nullptr;
};

}  // namespace facet
