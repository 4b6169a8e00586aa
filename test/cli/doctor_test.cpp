// `facet doctor`: the sections plugins contribute (Registrar::add_diagnostic).

#include <gtest/gtest.h>

#include <string>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

#ifdef FACET_TEST_PLUGINS_DIR
TEST(Doctor, PrintsEveryPluginSectionAndGoesOnPastOneThatThrows) {
  const std::string good = std::string(FACET_TEST_PLUGINS_DIR) + "/good";
  const auto result =
      run_cli("doctor --plugin-path " + shell_quote(good), "env -u FACET_PLUGIN_PATH");
  EXPECT_EQ(result.exit_code, 0) << result.out;
  // Each line of a section is indented under its title, in the order the plugin added them.
  const auto sensor = result.out.find(
      "Test sensor (from plugin good):\n  driver: constant 1.0\n  devices: test://0");
  const auto bus = result.out.find("Test bus (from plugin good):\n  error: bus not powered\n");
  ASSERT_NE(sensor, std::string::npos) << result.out;
  ASSERT_NE(bus, std::string::npos) << result.out;
  EXPECT_LT(sensor, bus) << result.out;
  // The sections come after the plugin list and the load failures.
  EXPECT_LT(result.out.find("load failures:"), sensor) << result.out;
}
#endif

#ifdef FACET_HAVE_OPENNI2
TEST(Doctor, ListsTheOpenNi2DriversAndTheDevicesItFinds) {
  const auto result = run_cli("doctor", "env -u FACET_PLUGIN_PATH");
  EXPECT_EQ(result.exit_code, 0) << result.out;
  for (const char* text : {"OpenNI2 (from plugin facet_openni2):", "  OpenNI2 2.", "drivers ",
                           "libOniFile.so  (.oni recordings)", "  devices:"}) {
    EXPECT_NE(result.out.find(text), std::string::npos) << text << "\n" << result.out;
  }
}
#endif

}  // namespace
}  // namespace facet::test
