#include "facet/testing/stage_runner.hpp"

#include <stdexcept>

namespace facet::testing {

StageRunnerBase::StageRunnerBase(StageSpec spec, const std::map<std::string, ParamValue>& overrides)
    : spec_(std::move(spec)), params_(spec_.default_params()) {
  for (const auto& [name, value] : overrides) {
    const ParamSpec* param = spec_.find_param(name);
    if (param == nullptr) {
      throw std::invalid_argument("stage '" + spec_.name() + "' has no parameter '" + name + "'");
    }
    if (const auto error = check_param_value(*param, value)) {
      throw std::invalid_argument("parameter '" + name + "': " + *error);
    }
    // Integers given for real parameters are stored as reals, as the graph loader does.
    params_.set(name, param->type == ParamType::real && std::holds_alternative<std::int64_t>(value)
                          ? ParamValue(static_cast<double>(std::get<std::int64_t>(value)))
                          : value);
  }
  pending_inputs_.resize(spec_.inputs().size());
}

StageRunnerBase::~StageRunnerBase() {
  try {
    close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
}

void StageRunnerBase::create() {
  stage_ = spec_.factory()(params_);
  ctx_ = std::make_unique<ProcessContext>(spec_, "runner");
}

void StageRunnerBase::set_input(std::string_view port, Packet packet) {
  for (std::size_t i = 0; i < spec_.inputs().size(); ++i) {
    if (spec_.inputs()[i].name == port) {
      // As in a graph, where every output is checked before a stage reads it (ProcessContext).
      if (std::string error = packet.format_error(); !error.empty()) {
        throw std::invalid_argument("input '" + std::string(port) + "' (" +
                                    std::string(packet.type_key()) + "): " + error);
      }
      pending_inputs_[i] = std::move(packet);
      return;
    }
  }
  throw std::invalid_argument("stage '" + spec_.name() + "' has no input '" + std::string(port) +
                              "'");
}

void StageRunnerBase::run() {
  if (!open_) {
    stage_->open(OpenContext{"runner"});
    open_ = true;
  }
  ctx_->begin_frame(frame_++);
  auto inputs = ctx_->inputs();
  for (std::size_t i = 0; i < inputs.size(); ++i)
    inputs[i] = pending_inputs_[i];
  stage_->process(*ctx_);
}

void StageRunnerBase::close() {
  if (open_) {
    open_ = false;
    stage_->close();
  }
}

const Packet& StageRunnerBase::output_packet(std::string_view port) const {
  for (std::size_t i = 0; i < spec_.outputs().size(); ++i) {
    if (spec_.outputs()[i].name == port) return ctx_->outputs()[i];
  }
  throw std::invalid_argument("stage '" + spec_.name() + "' has no output '" + std::string(port) +
                              "'");
}

}  // namespace facet::testing
