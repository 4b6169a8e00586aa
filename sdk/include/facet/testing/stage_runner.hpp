#pragma once
// StageRunner: runs one stage without a graph, a YAML file or a plugin — for unit tests.
//
//   facet::testing::StageRunner<MedianFilter> runner({{"size", std::int64_t{5}}});
//   runner.set_input("depth", facet::Packet::make(depth));
//   runner.run();
//   const auto& out = runner.output<facet::DepthImage>("depth");
//
// Parameters are checked against the stage's spec exactly as a graph would check them.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facet/stage.hpp"

namespace facet::testing {

class StageRunnerBase {
 public:
  // Validates `overrides` against `spec` and fills defaults; throws std::invalid_argument.
  StageRunnerBase(StageSpec spec, const std::map<std::string, ParamValue>& overrides);
  ~StageRunnerBase();
  StageRunnerBase(const StageRunnerBase&) = delete;
  StageRunnerBase& operator=(const StageRunnerBase&) = delete;

  void set_input(std::string_view port, Packet packet);
  // One process() call (opens the stage on the first call); inputs persist between calls.
  void run();
  // Closes the stage (also done by the destructor).
  void close();

  const Packet& output_packet(std::string_view port) const;
  template <class T>
  const T& output(std::string_view port) const {
    const T* value = output_packet(port).get_if<T>();
    if (value == nullptr) throw std::logic_error("output '" + std::string(port) + "' is empty");
    return *value;
  }
  const std::vector<Metric>& metrics() const { return ctx_->metrics(); }
  const std::vector<std::string>& warnings() const { return ctx_->warnings(); }
  bool at_end_of_stream() const { return ctx_->at_end_of_stream(); }
  const Params& params() const { return params_; }
  std::int64_t frames_run() const { return frame_; }

 protected:
  void create();

 private:
  StageSpec spec_;
  Params params_;
  std::unique_ptr<Stage> stage_;
  std::unique_ptr<ProcessContext> ctx_;
  std::vector<Packet> pending_inputs_;
  std::int64_t frame_ = 0;
  bool open_ = false;
};

template <class StageT>
class StageRunner : public StageRunnerBase {
 public:
  explicit StageRunner(const std::map<std::string, ParamValue>& overrides = {})
      : StageRunnerBase(with_factory(), overrides) {
    create();
  }

 private:
  static StageSpec with_factory() {
    StageSpec spec = StageT::spec();
    spec.factory(
        [](const Params& p) -> std::unique_ptr<Stage> { return std::make_unique<StageT>(p); });
    return spec;
  }
};

}  // namespace facet::testing
