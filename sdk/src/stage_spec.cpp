#include "facet/stage_spec.hpp"

#include <algorithm>
#include <stdexcept>

namespace facet {

std::string_view to_string(Concurrency concurrency) noexcept {
  switch (concurrency) {
    case Concurrency::serial:
      return "serial";
    case Concurrency::clonable:
      return "clonable";
    case Concurrency::reentrant:
      return "reentrant";
  }
  return "?";
}

StageSpec::StageSpec(std::string name, std::string doc)
    : name_(std::move(name)), doc_(std::move(doc)) {}

StageSpec& StageSpec::add_param(std::string name, ParamType type, ParamValue default_value,
                                std::string doc, ParamOptions opt) {
  return add_param(
      ParamSpec{std::move(name), type, std::move(default_value), std::move(doc), std::move(opt)});
}

StageSpec& StageSpec::add_param(ParamSpec spec) {
  // A declaration whose own default fails its range is a bug in the stage: fail loudly at load.
  if (const auto error = check_param_value(spec, spec.default_value)) {
    throw std::logic_error("stage '" + name_ + "': default of parameter '" + spec.name +
                           "': " + *error);
  }
  params_.push_back(std::move(spec));
  return *this;
}

StageSpec& StageSpec::param(std::string name, bool v, std::string doc, ParamOptions opt) {
  return add_param(std::move(name), ParamType::boolean, v, std::move(doc), std::move(opt));
}
StageSpec& StageSpec::param(std::string name, int v, std::string doc, ParamOptions opt) {
  return add_param(std::move(name), ParamType::integer, std::int64_t{v}, std::move(doc),
                   std::move(opt));
}
StageSpec& StageSpec::param(std::string name, std::int64_t v, std::string doc, ParamOptions opt) {
  return add_param(std::move(name), ParamType::integer, v, std::move(doc), std::move(opt));
}
StageSpec& StageSpec::param(std::string name, double v, std::string doc, ParamOptions opt) {
  return add_param(std::move(name), ParamType::real, v, std::move(doc), std::move(opt));
}
StageSpec& StageSpec::param(std::string name, const char* v, std::string doc, ParamOptions opt) {
  return add_param(std::move(name), ParamType::string, std::string(v), std::move(doc),
                   std::move(opt));
}
StageSpec& StageSpec::param(std::string name, std::string v, std::string doc, ParamOptions opt) {
  return add_param(std::move(name), ParamType::string, std::move(v), std::move(doc),
                   std::move(opt));
}

std::string StageSpec::summary() const {
  return doc_.substr(0, doc_.find('\n'));
}

namespace {
template <class T>
const T* find_named(const std::vector<T>& items, std::string_view name) {
  const auto it =
      std::find_if(items.begin(), items.end(), [&](const T& i) { return i.name == name; });
  return it == items.end() ? nullptr : &*it;
}
}  // namespace

const PortSpec* StageSpec::find_input(std::string_view port) const {
  return find_named(inputs_, port);
}
const PortSpec* StageSpec::find_output(std::string_view port) const {
  return find_named(outputs_, port);
}
const ParamSpec* StageSpec::find_param(std::string_view param) const {
  return find_named(params_, param);
}

Params StageSpec::default_params() const {
  Params params;
  for (const auto& p : params_)
    params.set(p.name, p.default_value);
  return params;
}

}  // namespace facet
