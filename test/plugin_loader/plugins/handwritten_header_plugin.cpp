// A plugin header written by hand instead of by FACET_PLUGIN, so that each field can be made
// wrong on purpose. The build sets one FACET_TEST_* definition per broken case.
//
// register_stages aborts: the host must refuse the header before calling any of this C++.

#include <facet/plugin_abi.h>

#include <cstdlib>
#include <facet/version.hpp>

#ifndef FACET_TEST_MAGIC
#define FACET_TEST_MAGIC FACET_PLUGIN_MAGIC
#endif
#ifndef FACET_TEST_ABI_VERSION
#define FACET_TEST_ABI_VERSION FACET_PLUGIN_ABI_VERSION
#endif
#ifndef FACET_TEST_HEADER_SIZE
#define FACET_TEST_HEADER_SIZE sizeof(facet_plugin_header)
#endif
#ifndef FACET_TEST_SDK_MINOR
#define FACET_TEST_SDK_MINOR FACET_SDK_VERSION_MINOR
#endif
#ifndef FACET_TEST_TOOLCHAIN
#define FACET_TEST_TOOLCHAIN FACET_TOOLCHAIN_FINGERPRINT
#endif

extern "C" __attribute__((visibility("default"))) const facet_plugin_header* facet_plugin_entry() {
  static const facet_plugin_header header = {FACET_TEST_MAGIC,
                                             FACET_TEST_ABI_VERSION,
                                             static_cast<uint32_t>(FACET_TEST_HEADER_SIZE),
                                             FACET_SDK_VERSION_MAJOR,
                                             FACET_TEST_SDK_MINOR,
                                             FACET_SDK_VERSION_PATCH,
                                             FACET_TEST_TOOLCHAIN,
                                             "handwritten",
                                             "0.0.1",
                                             [](void*) { std::abort(); }};
  return &header;
}
