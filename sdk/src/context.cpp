#include "facet/context.hpp"

#include <stdexcept>

namespace facet {
namespace {

std::size_t index_of(const std::vector<PortSpec>& ports, std::string_view port) {
  for (std::size_t i = 0; i < ports.size(); ++i) {
    if (ports[i].name == port) return i;
  }
  return ports.size();
}

}  // namespace

ProcessContext::ProcessContext(const StageSpec& spec, std::string node_id)
    : spec_(&spec),
      node_id_(std::move(node_id)),
      inputs_(spec.inputs().size()),
      outputs_(spec.outputs().size()) {}

const Packet& ProcessContext::input_packet(std::string_view port) const {
  const std::size_t i = index_of(spec_->inputs(), port);
  if (i == inputs_.size()) {
    throw std::logic_error("stage '" + spec_->name() + "' has no input port '" + std::string(port) +
                           "'");
  }
  return inputs_[i];
}

std::size_t ProcessContext::output_index(std::string_view port) const {
  const std::size_t i = index_of(spec_->outputs(), port);
  if (i == outputs_.size()) {
    throw std::logic_error("stage '" + spec_->name() + "' has no output port '" +
                           std::string(port) + "'");
  }
  return i;
}

void ProcessContext::output_packet(std::string_view port, Packet packet) {
  const std::size_t i = output_index(port);
  const auto& expected = spec_->outputs()[i].type_key;
  if (!packet.empty() && packet.type_key() != expected) {
    throw std::logic_error("stage '" + spec_->name() + "' wrote a " +
                           std::string(packet.type_key()) + " to output '" + std::string(port) +
                           "', declared as " + expected);
  }
  if (std::string error = packet.format_error(); !error.empty()) {
    throw StageError("output '" + std::string(port) + "' (" + expected + "): " + error);
  }
  outputs_[i] = std::move(packet);
}

void ProcessContext::throw_bad_input(std::string_view port, std::string_view expected) const {
  const Packet& packet = input_packet(port);
  if (packet.empty()) {
    throw StageError("input '" + std::string(port) + "' is empty");
  }
  throw StageError("input '" + std::string(port) + "' holds a " + std::string(packet.type_key()) +
                   ", expected " + std::string(expected));
}

void ProcessContext::begin_frame(std::int64_t frame_index) {
  frame_index_ = frame_index;
  for (auto& out : outputs_)
    out = Packet();
  metrics_.clear();
  warnings_.clear();
  end_of_stream_ = false;
}

}  // namespace facet
