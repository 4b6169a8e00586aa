// Misuses of facet/contract.hpp that must not compile, each with a message that says what to do.
// Built with -fsyntax-only by the tests Contract.Misuse* (test/CMakeLists.txt), one case each.
#include "facet/contract.hpp"

namespace {

struct NotRegistered {
  int value = 0;
};

#if FACET_MISUSE_CASE == 1
// A port of a type without FACET_TYPE_KEY.
const facet::In<NotRegistered> kPort{"port", "A port of an unregistered type."};
#elif FACET_MISUSE_CASE == 2
// A parameter of a type without ParamTraits.
const facet::Param<NotRegistered> kParam{"param", NotRegistered{}, "An unregistered type."};
#elif FACET_MISUSE_CASE == 3
// A float parameter: the spec stores doubles, so it is not offered.
const facet::Param<float> kParam{"param", 1.0F, "A float."};
#else
// The control: the same file with registered types compiles.
const facet::Param<double> kParam{"param", 1.0, "A double."};
#endif

}  // namespace
