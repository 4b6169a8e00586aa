#pragma once
// The static contract of a stage: what `facet inspect` prints and what graphs are validated
// against. It is built without an instance, from the stage class's static spec().

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "facet/packet.hpp"
#include "facet/param.hpp"

namespace facet {

class Stage;

// How the executor may run a stage when several frames are in flight.
enum class Concurrency {
  serial,     // one instance, frames strictly in order (sources, sinks, trackers)
  clonable,   // independent instances may process different frames at once
  reentrant,  // one instance may process several frames at once (process() is thread-safe)
};

std::string_view to_string(Concurrency concurrency) noexcept;

struct PortSpec {
  std::string name;
  std::string type_key;  // e.g. "facet.DepthImage/1"
  std::string doc;
  bool required = true;  // inputs only: a required input must be connected in every graph
};

using StageFactory = std::function<std::unique_ptr<Stage>(const Params&)>;

class StageSpec {
 public:
  // `name` is "family.variant" (e.g. "normals.cross"); `doc` starts with a one-line summary.
  StageSpec(std::string name, std::string doc);

  template <class T>
  StageSpec& input(std::string name, std::string doc) {
    inputs_.push_back({std::move(name), std::string(type_key<T>()), std::move(doc), true});
    return *this;
  }
  template <class T>
  StageSpec& optional_input(std::string name, std::string doc) {
    inputs_.push_back({std::move(name), std::string(type_key<T>()), std::move(doc), false});
    return *this;
  }
  template <class T>
  StageSpec& output(std::string name, std::string doc) {
    outputs_.push_back({std::move(name), std::string(type_key<T>()), std::move(doc), true});
    return *this;
  }

  StageSpec& param(std::string name, bool default_value, std::string doc, ParamOptions opt = {});
  StageSpec& param(std::string name, int default_value, std::string doc, ParamOptions opt = {});
  StageSpec& param(std::string name, std::int64_t default_value, std::string doc,
                   ParamOptions opt = {});
  StageSpec& param(std::string name, double default_value, std::string doc, ParamOptions opt = {});
  StageSpec& param(std::string name, const char* default_value, std::string doc,
                   ParamOptions opt = {});
  StageSpec& param(std::string name, std::string default_value, std::string doc,
                   ParamOptions opt = {});

  // Declares typed ports and parameters (facet/contract.hpp) in the order given, the order
  // `facet inspect` lists them in.
  template <class... Descriptor>
  StageSpec& declare(const Descriptor&... descriptors) {
    (descriptors.declare_in(*this), ...);
    return *this;
  }

  // A parameter declared whole; the default must pass its own checks (std::logic_error if not:
  // a bug in the stage, reported when the plugin loads).
  StageSpec& add_param(ParamSpec param);

  StageSpec& concurrency(Concurrency value) {
    concurrency_ = value;
    return *this;
  }

  // A source has no inputs and ends the stream by calling ProcessContext::end_of_stream().
  bool is_source() const { return inputs_.empty(); }

  const std::string& name() const { return name_; }
  const std::string& doc() const { return doc_; }
  std::string summary() const;  // first line of doc
  const std::vector<PortSpec>& inputs() const { return inputs_; }
  const std::vector<PortSpec>& outputs() const { return outputs_; }
  const std::vector<ParamSpec>& params() const { return params_; }
  Concurrency concurrency() const { return concurrency_; }

  const PortSpec* find_input(std::string_view port) const;
  const PortSpec* find_output(std::string_view port) const;
  const ParamSpec* find_param(std::string_view param) const;

  // Every declared parameter at its default.
  Params default_params() const;

  // Set by Registrar::add<T>(); creates an instance from validated parameters.
  const StageFactory& factory() const { return factory_; }
  StageSpec& factory(StageFactory factory) {
    factory_ = std::move(factory);
    return *this;
  }

 private:
  StageSpec& add_param(std::string name, ParamType type, ParamValue default_value, std::string doc,
                       ParamOptions opt);

  std::string name_;
  std::string doc_;
  std::vector<PortSpec> inputs_;
  std::vector<PortSpec> outputs_;
  std::vector<ParamSpec> params_;
  Concurrency concurrency_ = Concurrency::serial;
  StageFactory factory_;
};

}  // namespace facet
