#pragma once
// SDK version and the toolchain fingerprint that plugin and host must share.

// <version> pulls in the standard library configuration, which defines the ABI macros tested below;
// without it the fingerprint would depend on what the including file happened to include first.
#include <version>

#include "facet/sdk_version.h"  // generated: FACET_SDK_VERSION_{MAJOR,MINOR,PATCH}

#define FACET_STRINGIFY_IMPL(x) #x
#define FACET_STRINGIFY(x) FACET_STRINGIFY_IMPL(x)

// C++ types cross the plugin boundary (std::string, std::function, cv::Mat inside packets), so the
// host and a plugin must agree on the C++ ABI: compiler family and major version, standard
// library and its string ABI, and architecture. A mismatch is refused before any C++ is called.
#if defined(__clang__)
#define FACET_COMPILER_ID "clang-" FACET_STRINGIFY(__clang_major__)
#elif defined(__GNUC__)
#define FACET_COMPILER_ID "gcc-" FACET_STRINGIFY(__GNUC__)
#else
#define FACET_COMPILER_ID "unknown-compiler"
#endif

#if defined(_GLIBCXX_USE_CXX11_ABI)
#define FACET_STDLIB_ID "libstdc++-cxx11abi" FACET_STRINGIFY(_GLIBCXX_USE_CXX11_ABI)
#elif defined(_LIBCPP_VERSION)
#define FACET_STDLIB_ID "libc++"
#else
#define FACET_STDLIB_ID "unknown-stdlib"
#endif

#if defined(__x86_64__)
#define FACET_ARCH_ID "x86_64"
#elif defined(__aarch64__)
#define FACET_ARCH_ID "aarch64"
#else
#define FACET_ARCH_ID "unknown-arch"
#endif

#define FACET_TOOLCHAIN_FINGERPRINT FACET_ARCH_ID "/" FACET_COMPILER_ID "/" FACET_STDLIB_ID

namespace facet {

struct SdkVersion {
  int major;
  int minor;
  int patch;
};

inline constexpr SdkVersion kSdkVersion{FACET_SDK_VERSION_MAJOR, FACET_SDK_VERSION_MINOR,
                                        FACET_SDK_VERSION_PATCH};

// The fingerprint the SDK library itself was compiled with (the host's side of the check).
const char* sdk_toolchain_fingerprint() noexcept;

}  // namespace facet
