#pragma once
// Packet: an immutable, shared, type-erased value travelling along one edge of a graph.
//
// Types are identified by a stable string key ("facet.DepthImage/1"), never by typeid: typeid of
// the same type can differ between shared libraries, and a key survives renames of the C++ type.
// Packets share their payload, so fanning one output out to N consumers copies no image.

#include <concepts>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "facet/types/frame.hpp"

namespace facet {

// Specialise with FACET_TYPE_KEY(Type, "facet.Name/version") next to the type's definition.
template <class T>
struct TypeKey;

#define FACET_TYPE_KEY(Type, key_literal)                  \
  template <>                                              \
  struct facet::TypeKey<Type> {                            \
    static constexpr std::string_view value = key_literal; \
  }

template <class T>
constexpr std::string_view type_key() {
  return TypeKey<T>::value;
}

class Packet {
 public:
  Packet() = default;

  template <class T>
  static Packet make(T value) {
    return share<T>(std::make_shared<const T>(std::move(value)));
  }

  template <class T>
  static Packet share(std::shared_ptr<const T> value) {
    const FrameHeader* header = nullptr;
    if constexpr (std::derived_from<T, FrameHeader>) header = value.get();
    FormatCheck check = nullptr;
    if constexpr (requires(const T& v) {
                    { v.format_error() } -> std::convertible_to<std::string>;
                  }) {
      check = [](const void* payload) { return static_cast<const T*>(payload)->format_error(); };
    }
    return Packet(std::move(value), facet::type_key<T>(), header, check);
  }

  bool empty() const noexcept { return data_ == nullptr; }
  explicit operator bool() const noexcept { return !empty(); }
  std::string_view type_key() const noexcept { return key_; }

  // Null when empty or of another type.
  template <class T>
  const T* get_if() const noexcept {
    return (data_ && key_ == facet::type_key<T>()) ? static_cast<const T*>(data_.get()) : nullptr;
  }

  // Shared ownership of the payload, or null when empty or of another type.
  template <class T>
  std::shared_ptr<const T> shared_as() const noexcept {
    if (get_if<T>() == nullptr) return nullptr;
    return std::static_pointer_cast<const T>(data_);
  }

  // Identity of the payload: two packets with the same address share one value.
  const void* address() const noexcept { return data_.get(); }

  // The frame and camera of a payload that carries them (a type derived from FrameHeader: every
  // image, the planes, the objects), whatever its type; null for other payloads. This is how the
  // executor names a frame's files without knowing any image type.
  const FrameHeader* header() const noexcept { return header_; }

  // What is wrong with the payload's format, or "" when it keeps it (or is empty, or of a type
  // that promises none). A type promises a format with a member `std::string format_error()
  // const`, as the image types do (facet/types/images.hpp); the executor checks every output
  // with it, so that a consumer can rely on the format of what it reads.
  std::string format_error() const {
    return check_ != nullptr ? check_(data_.get()) : std::string();
  }

 private:
  using FormatCheck = std::string (*)(const void* payload);

  Packet(std::shared_ptr<const void> data, std::string_view key, const FrameHeader* header,
         FormatCheck check)
      : data_(std::move(data)), key_(key), header_(header), check_(check) {}

  std::shared_ptr<const void> data_;
  // Points at a string literal with static storage (see FACET_TYPE_KEY); compared by content.
  std::string_view key_;
  const FrameHeader* header_ = nullptr;  // into *data_, which it shares the lifetime of
  FormatCheck check_ = nullptr;          // of the payload's type; null when it promises no format
};

}  // namespace facet
