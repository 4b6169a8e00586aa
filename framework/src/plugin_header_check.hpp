#pragma once
// Checks a plugin's C header against this host before any of the plugin's C++ is called.

#include <optional>
#include <string>

#include "facet/plugin_abi.h"

namespace facet::detail {

// The reason the header is refused (both sides of the mismatch spelled out), or nothing when the
// plugin may be registered. Only plain C fields are read, in an order where each check makes the
// next one meaningful: magic, then ABI version, then the header's size, then the rest.
std::optional<std::string> check_plugin_header(const facet_plugin_header& header);

// "0.1.2", as the plugin's header states it.
std::string plugin_sdk_version(const facet_plugin_header& header);

}  // namespace facet::detail
