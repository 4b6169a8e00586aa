#pragma once
// Typed contracts: each port and parameter of a stage is declared once, as a descriptor that both
// builds the stage's spec and reads the value, so a name or a type is never written twice.
//
//   namespace {
//   const facet::In<facet::DepthImage> kDepth{"depth", "Depth image, CV_16UC1 in mm ..."};
//   const facet::Out<facet::NormalImage> kNormals{"normals", "CV_32FC3 unit normals ..."};
//   const facet::Param<int> kRadius{"radius", 2, "Distance r of the neighbours.",
//                                   {.unit = "px", .min = 1, .max = 16, .origin = "paper"}};
//   const facet::EnumParam<Triangle> kTriangle{"triangle", Triangle::paper,
//                                              {{Triangle::paper, "paper"},
//                                               {Triangle::centred, "centred"}},
//                                              "Neighbours spanning the tangents."};
//   }  // namespace
//
//   facet::StageSpec CrossStage::spec() {
//     facet::StageSpec spec("normals.cross", "...");
//     return spec.declare(kDepth, kNormals, kRadius, kTriangle);
//   }
//   CrossStage::CrossStage(const facet::Params& params)
//       : radius_px_(kRadius(params)), triangle_(kTriangle(params)) {}
//   void CrossStage::process(facet::ProcessContext& ctx) {
//     const facet::DepthImage& depth = kDepth(ctx);
//     ...
//     kNormals(ctx, std::move(normals));
//   }
//
// A parameter of a type of one's own (a box, a vector) is written as text in a graph and parsed
// by its ParamTraits; `facet validate` runs the parser, so a bad value is reported with the file,
// line and column of the graph before any stage is built:
//
//   template <>
//   struct facet::ParamTraits<Box> {
//     static std::variant<Box, std::string> parse(std::string_view text);  // value or error
//     static std::string format(const Box& value);
//   };
//   const facet::Param<Box> kWorkspace{"workspace", Box{}, "Where objects may be."};
//
// Descriptors are immutable objects at namespace scope in the stage's source file; they hold the
// documentation that `facet inspect` prints.

#include <concepts>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "facet/context.hpp"
#include "facet/packet.hpp"
#include "facet/param.hpp"
#include "facet/stage_spec.hpp"

namespace facet {

// ---------------------------------------------------------------------------------------------
// Ports

// A type that may travel in a packet: registered with FACET_TYPE_KEY next to its definition.
template <class T>
concept PacketType = requires {
  { TypeKey<T>::value } -> std::convertible_to<std::string_view>;
};

namespace contract_detail {
template <class T>
constexpr void require_packet_type() {
  static_assert(PacketType<T>,
                "facet::In<T> / facet::Out<T>: T is not a packet type. Register it next to its "
                "definition with FACET_TYPE_KEY(T, \"vendor.Name/1\") (facet/packet.hpp), or use "
                "one of the types in facet/types/.");
}
}  // namespace contract_detail

// A required input: the graph must connect it. Reading it throws StageError naming the port when
// the frame has no packet there.
template <class T>
class In {
 public:
  In(std::string name, std::string doc) : name_(std::move(name)), doc_(std::move(doc)) {
    contract_detail::require_packet_type<T>();
  }

  const T& operator()(const ProcessContext& ctx) const { return ctx.input<T>(name_); }
  std::shared_ptr<const T> shared(const ProcessContext& ctx) const {
    return ctx.input_shared<T>(name_);
  }
  // The packet itself, to forward it to an output without touching the payload.
  const Packet& packet(const ProcessContext& ctx) const { return ctx.input_packet(name_); }

  const std::string& name() const { return name_; }
  void declare_in(StageSpec& spec) const { spec.input<T>(name_, doc_); }

 private:
  std::string name_;
  std::string doc_;
};

// An input a graph may leave unconnected (or a frame may leave empty).
template <class T>
class OptionalIn {
 public:
  OptionalIn(std::string name, std::string doc) : name_(std::move(name)), doc_(std::move(doc)) {
    contract_detail::require_packet_type<T>();
  }

  // Null when the port is not connected or has no packet this frame; throws StageError when
  // the packet is of another type.
  const T* operator()(const ProcessContext& ctx) const {
    return ctx.has_input(name_) ? &ctx.input<T>(name_) : nullptr;
  }
  std::shared_ptr<const T> shared(const ProcessContext& ctx) const {
    return ctx.has_input(name_) ? ctx.input_shared<T>(name_) : nullptr;
  }
  bool present(const ProcessContext& ctx) const { return ctx.has_input(name_); }

  const std::string& name() const { return name_; }
  void declare_in(StageSpec& spec) const { spec.optional_input<T>(name_, doc_); }

 private:
  std::string name_;
  std::string doc_;
};

template <class T>
class Out {
 public:
  Out(std::string name, std::string doc) : name_(std::move(name)), doc_(std::move(doc)) {
    contract_detail::require_packet_type<T>();
  }

  void operator()(ProcessContext& ctx, T value) const { ctx.output<T>(name_, std::move(value)); }
  // Publishes a payload that is already shared (no copy).
  void share(ProcessContext& ctx, std::shared_ptr<const T> value) const {
    ctx.output_packet(name_, Packet::share<T>(std::move(value)));
  }
  // Forwards a packet of this port's type (typically an input) without copying its payload;
  // throws std::logic_error for a packet of another type (a programming error).
  void forward(ProcessContext& ctx, Packet packet) const {
    if (!packet.empty() && packet.type_key() != type_key<T>()) {
      throw std::logic_error("output '" + name_ + "': forwarded a " +
                             std::string(packet.type_key()) + " packet, declared " +
                             std::string(type_key<T>()));
    }
    ctx.output_packet(name_, std::move(packet));
  }

  const std::string& name() const { return name_; }
  void declare_in(StageSpec& spec) const { spec.output<T>(name_, doc_); }

 private:
  std::string name_;
  std::string doc_;
};

// ---------------------------------------------------------------------------------------------
// Parameters

// How a parameter type is written in a graph. Specialise it for a type of one's own with
//   static std::variant<T, std::string> parse(std::string_view text);  // the value or an error
//   static std::string format(const T& value);                         // parse(format(v)) == v
// The built-in types (bool, int, std::int64_t, double, std::string) need nothing.
template <class T>
struct ParamTraits;

template <class T>
concept BuiltinParamType = std::same_as<T, bool> || std::same_as<T, int> ||
    std::same_as<T, std::int64_t> || std::same_as<T, double> || std::same_as<T, std::string>;

template <class T>
concept TextParamType = requires(std::string_view text, const T& value) {
  { ParamTraits<T>::parse(text) } -> std::same_as<std::variant<T, std::string>>;
  { ParamTraits<T>::format(value) } -> std::convertible_to<std::string>;
};

namespace contract_detail {

template <class T>
constexpr ParamType builtin_type() {
  if constexpr (std::same_as<T, bool>) return ParamType::boolean;
  if constexpr (std::same_as<T, int> || std::same_as<T, std::int64_t>) return ParamType::integer;
  if constexpr (std::same_as<T, double>) return ParamType::real;
  if constexpr (std::same_as<T, std::string>) return ParamType::string;
}

template <class T>
ParamValue builtin_store(const T& value) {
  if constexpr (std::same_as<T, int>)
    return std::int64_t{value};
  else
    return value;
}

template <class T>
T builtin_load(const ParamValue& value) {
  if constexpr (std::same_as<T, int>)
    return static_cast<int>(std::get<std::int64_t>(value));
  else if constexpr (std::same_as<T, double>)
    return std::holds_alternative<std::int64_t>(value)
               ? static_cast<double>(std::get<std::int64_t>(value))
               : std::get<double>(value);
  else
    return std::get<T>(value);
}

// An int parameter must fit an int whatever range its options give.
std::optional<std::string> check_fits_int(const ParamValue& value);

}  // namespace contract_detail

template <class T>
class Param {
  static_assert(BuiltinParamType<T> || TextParamType<T>,
                "facet::Param<T>: T is not a parameter type. Use bool, int, std::int64_t, double "
                "or std::string; an enum through facet::EnumParam<E>; or specialise "
                "facet::ParamTraits<T> with static std::variant<T, std::string> "
                "parse(std::string_view) and static std::string format(const T&) "
                "(facet/contract.hpp).");

 public:
  Param(std::string name, T default_value, std::string doc, ParamOptions options = {})
      : spec_{std::move(name), type(), store(default_value), std::move(doc), std::move(options)} {
    if constexpr (std::same_as<T, int>) {
      spec_.check = contract_detail::check_fits_int;
    } else if constexpr (!BuiltinParamType<T>) {
      spec_.check = [](const ParamValue& value) -> std::optional<std::string> {
        auto parsed = ParamTraits<T>::parse(std::get<std::string>(value));
        if (auto* error = std::get_if<std::string>(&parsed)) return std::move(*error);
        return std::nullopt;
      };
    }
  }

  // The validated value: every parameter of a built stage has passed the spec's checks.
  T operator()(const Params& params) const { return load(params.at(spec_.name)); }

  const std::string& name() const { return spec_.name; }
  void declare_in(StageSpec& spec) const { spec.add_param(spec_); }

 private:
  static constexpr ParamType type() {
    if constexpr (BuiltinParamType<T>)
      return contract_detail::builtin_type<T>();
    else
      return ParamType::string;
  }
  static ParamValue store(const T& value) {
    if constexpr (BuiltinParamType<T>)
      return contract_detail::builtin_store(value);
    else
      return std::string(ParamTraits<T>::format(value));
  }
  static T load(const ParamValue& value) {
    if constexpr (BuiltinParamType<T>) {
      return contract_detail::builtin_load<T>(value);
    } else {
      auto parsed = ParamTraits<T>::parse(std::get<std::string>(value));
      if (auto* error = std::get_if<std::string>(&parsed)) throw StageError(*error);
      return std::get<T>(std::move(parsed));
    }
  }

  ParamSpec spec_;
};

// A choice among named values of an enum: written by name in a graph, read as the enum.
template <class E>
requires std::is_enum_v<E>
class EnumParam {
 public:
  struct Choice {
    E value;
    std::string name;
  };

  EnumParam(std::string name, E default_value, std::vector<Choice> choices, std::string doc,
            ParamOptions options = {})
      : choices_(std::move(choices)) {
    for (const auto& choice : choices_)
      options.choices.emplace_back(choice.name);
    spec_ = ParamSpec{std::move(name), ParamType::string, ParamValue(name_of(default_value)),
                      std::move(doc), std::move(options)};
  }

  E operator()(const Params& params) const {
    const std::string& text = std::get<std::string>(params.at(spec_.name));
    for (const auto& choice : choices_) {
      if (choice.name == text) return choice.value;
    }
    throw StageError("parameter '" + spec_.name + "': '" + text + "' is not one of its choices");
  }

  // The name a value is written with (for messages and metrics).
  const std::string& name_of(E value) const {
    for (const auto& choice : choices_) {
      if (choice.value == value) return choice.name;
    }
    throw std::logic_error("parameter '" + spec_.name + "': a value without a name");
  }

  const std::string& name() const { return spec_.name; }
  void declare_in(StageSpec& spec) const { spec.add_param(spec_); }

 private:
  std::vector<Choice> choices_;
  ParamSpec spec_;
};

// ---------------------------------------------------------------------------------------------
}  // namespace facet
