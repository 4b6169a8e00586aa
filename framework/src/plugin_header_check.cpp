#include "plugin_header_check.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <string_view>

#include "facet/version.hpp"

namespace facet::detail {

std::optional<std::string> check_plugin_header(const facet_plugin_header& header) {
  if (header.magic != FACET_PLUGIN_MAGIC) {
    return fmt::format(
        "not a facet plugin header: magic number is {:#010x}, host expects {:#010x} (\"FCET\")",
        header.magic, FACET_PLUGIN_MAGIC);
  }
  // The ABI version decides the layout of everything after it, so it is checked before any
  // other field is trusted.
  if (header.abi_version != FACET_PLUGIN_ABI_VERSION) {
    return fmt::format("ABI version mismatch: plugin has {}, host expects {}", header.abi_version,
                       FACET_PLUGIN_ABI_VERSION);
  }
  if (header.header_size < sizeof(facet_plugin_header)) {
    return fmt::format("plugin header too small: plugin has {} bytes, host expects at least {}",
                       header.header_size, sizeof(facet_plugin_header));
  }
  // Within one major.minor the SDK keeps its C++ types' layout; patch releases may differ.
  const auto host = kSdkVersion;
  if (header.sdk_version_major != static_cast<std::uint32_t>(host.major) ||
      header.sdk_version_minor != static_cast<std::uint32_t>(host.minor)) {
    return fmt::format(
        "SDK version mismatch: plugin was built with SDK {}, host has SDK {}.{}.{} "
        "(major.minor must match); rebuild the plugin against this SDK",
        plugin_sdk_version(header), host.major, host.minor, host.patch);
  }
  const char* host_toolchain = sdk_toolchain_fingerprint();
  if (header.toolchain == nullptr || std::string_view(header.toolchain) != host_toolchain) {
    return fmt::format(
        "toolchain mismatch: plugin was built with '{}', host with '{}'; rebuild the plugin with "
        "the host's compiler and standard library",
        header.toolchain == nullptr ? "(none)" : header.toolchain, host_toolchain);
  }
  if (header.plugin_name == nullptr || *header.plugin_name == '\0') {
    return std::string("plugin header has no plugin name");
  }
  if (header.register_stages == nullptr) {
    return std::string("plugin header has no register_stages function");
  }
  return std::nullopt;
}

std::string plugin_sdk_version(const facet_plugin_header& header) {
  return fmt::format("{}.{}.{}", header.sdk_version_major, header.sdk_version_minor,
                     header.sdk_version_patch);
}

}  // namespace facet::detail
