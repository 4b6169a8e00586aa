// io.openni2 without a camera: every error path a user meets (no device, a missing or broken
// recording, a mode the device does not offer), and live frames from "Dummy", the virtual
// device of OpenNI2's own test driver (320x240 @ 30 fps, 1 mm, no field of view, no mirroring,
// no registration; its first image row is 2000 mm, its timestamps frame number * 33 ms).

#include "openni2/openni_source.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <thread>

#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "openni2/openni_doctor.hpp"
#include "temp_dir.hpp"

namespace facet::openni2 {
namespace {

using ::testing::HasSubstr;
using Runner = facet::testing::StageRunner<OpenNi2Source>;

const std::map<std::string, ParamValue> kDummy = {
    {"uri", std::string("Dummy")}, {"fx", 300.0}, {"fy", 300.0}, {"cx", 160.0}, {"cy", 120.0}};

std::map<std::string, ParamValue> dummy_with(const std::string& name, ParamValue value) {
  auto params = kDummy;
  params[name] = std::move(value);
  return params;
}

// The message of the StageError the first frame (which opens the source) throws.
std::string open_error(const std::map<std::string, ParamValue>& params) {
  Runner runner(params);
  try {
    runner.run();
  } catch (const StageError& error) {
    return error.what();
  }
  ADD_FAILURE() << "the source opened";
  return "";
}

double metric(const Runner& runner, const std::string& name) {
  for (const auto& m : runner.metrics()) {
    if (m.name == name) return m.value;
  }
  ADD_FAILURE() << "no metric " << name;
  return -1.0;
}

TEST(OpenNi2Source, UrisOfRecordingsAndDevicesAreToldApart) {
  test::TempDir dir("facet-openni2");
  std::ofstream(dir / "take") << "x";
  EXPECT_TRUE(names_a_recording("missing.oni"));
  EXPECT_TRUE(names_a_recording("/data/TAKE.ONI"));
  EXPECT_TRUE(names_a_recording((dir / "take").string()));  // an existing file, any name
  EXPECT_FALSE(names_a_recording(""));
  EXPECT_FALSE(names_a_recording("1d27/0601@2/5"));
  EXPECT_FALSE(names_a_recording("Dummy"));
}

TEST(OpenNi2Source, AMissingRecordingIsNamed) {
  const std::string error = open_error({{"uri", std::string("/no/such/take.oni")}});
  EXPECT_THAT(error, HasSubstr("recording '/no/such/take.oni' does not exist"));
}

TEST(OpenNi2Source, AFileThatIsNoRecordingIsNamedWithWhatOpenNi2Said) {
  test::TempDir dir("facet-openni2");
  for (const char* name : {"garbage.oni", "notes.txt"}) {
    const auto file = dir / name;
    std::ofstream(file) << "this is not an OpenNI recording\n";
    const std::string error = open_error({{"uri", file.string()}});
    EXPECT_THAT(error, HasSubstr("cannot play recording '" + file.string() + "'"));
    EXPECT_THAT(error, HasSubstr("OpenNI2 says: "));
    EXPECT_THAT(error, HasSubstr("Couldn't open device"));  // OpenNI2's own words
  }
}

TEST(OpenNi2Source, AnUnknownDeviceUriIsNamed) {
  const std::string error = open_error({{"uri", std::string("1d27/0601@9/9")}});
  EXPECT_THAT(error, HasSubstr("cannot open OpenNI2 device '1d27/0601@9/9'"));
  EXPECT_THAT(error, HasSubstr("OpenNI2 says: "));
}

TEST(OpenNi2Source, TheFirstDeviceIsOpenedOrItsAbsenceSaidPlainly) {
  // Checked both ways, so that the test means something on a machine with a camera too.
  const bool have_device = openni_doctor_report().find("devices: none found") == std::string::npos;
  Runner runner({{"uri", std::string("")}, {"fx", 500.0}, {"fy", 500.0}});
  if (have_device) {
    EXPECT_NO_THROW(runner.run());
    return;
  }
  try {
    runner.run();
    ADD_FAILURE() << "opened a device that OpenNI2 does not list";
  } catch (const StageError& error) {
    EXPECT_THAT(error.what(), HasSubstr("no OpenNI2 device to open (uri \"\""));
    EXPECT_THAT(error.what(), HasSubstr("no devices found"));  // OpenNI2's own words
    EXPECT_THAT(error.what(), HasSubstr("facet doctor"));
  }
}

TEST(OpenNi2Source, AVideoModeTheDeviceDoesNotOfferIsRefusedWithTheModesItHas) {
  const std::string error = open_error(dummy_with("width", std::int64_t{640}));
  EXPECT_THAT(error, HasSubstr("'Dummy' has no depth mode in millimetres with 640 width"));
  EXPECT_THAT(error, HasSubstr("supported modes: 320x240 @ 30 fps, 1 mm"));
  EXPECT_THAT(open_error(dummy_with("fps", std::int64_t{60})), HasSubstr("60 fps"));
}

TEST(OpenNi2Source, RegistrationAndMirroringADeviceCannotDoAreRefused) {
  EXPECT_THAT(open_error(dummy_with("registration", true)),
              HasSubstr("OpenNI2 device 'Dummy' cannot register depth to colour"));
  EXPECT_THAT(open_error(dummy_with("mirror", true)),
              HasSubstr("OpenNI2 device 'Dummy' does not support mirroring"));
}

TEST(OpenNi2Source, ADeviceWithoutFieldOfViewNeedsTheIntrinsicsGiven) {
  const std::string error = open_error({{"uri", std::string("Dummy")}});
  EXPECT_THAT(error, HasSubstr("reports no field of view"));
  EXPECT_THAT(error, HasSubstr("give fx, fy, cx, cy"));
}

TEST(OpenNi2Source, BadParametersAreRefusedBeforeAnyDeviceIsOpened) {
  EXPECT_THROW(Runner(dummy_with("speed", 0.0)), StageError);
  EXPECT_THROW(Runner({{"uri", std::string("Dummy")}, {"fx", 300.0}}), StageError);
  EXPECT_THROW(Runner(dummy_with("policy", std::string("newest"))), std::invalid_argument);
}

TEST(OpenNi2Source, LiveFramesCarryIndexStemDeviceTimeAndIntrinsics) {
  Runner runner(dummy_with("policy", std::string("block")));
  std::int64_t previous_ns = 0;
  for (int frame = 0; frame < 3; ++frame) {
    runner.run();
    ASSERT_FALSE(runner.at_end_of_stream());
    const auto& depth = runner.output<DepthImage>("depth");
    ASSERT_TRUE(depth.in_millimetres());
    EXPECT_EQ(depth.depth.cols, 320);
    EXPECT_EQ(depth.depth.rows, 240);
    EXPECT_EQ(depth.frame.index, frame);
    EXPECT_EQ(depth.frame.stem, "frame_00000" + std::to_string(frame));
    // Microseconds from the device, in ns: a multiple of the driver's 33 ms, growing.
    EXPECT_EQ(depth.frame.timestamp_ns % 33'000'000, 0) << depth.frame.timestamp_ns;
    EXPECT_GT(depth.frame.timestamp_ns, previous_ns);
    previous_ns = depth.frame.timestamp_ns;
    // The pixels are the device's (its top row is 2000 mm), copied row by row.
    EXPECT_EQ(depth.depth.at<std::uint16_t>(0, 0), 2000);
    EXPECT_EQ(depth.depth.at<std::uint16_t>(0, 319), 2000);
    EXPECT_EQ(depth.camera.fx, 300.0);
    EXPECT_EQ(depth.camera.cx, 160.0);
    EXPECT_EQ(depth.camera.width, 320);
    EXPECT_EQ(depth.camera.height, 240);
  }
}

TEST(OpenNi2Source, TheLatestPolicyDropsStaleFramesAndCountsThem) {
  Runner runner(dummy_with("policy", std::string("latest")));
  runner.run();
  const std::int64_t first_ns = runner.output<DepthImage>("depth").frame.timestamp_ns;
  // A graph busy for a long while (15 frame periods of the device): the next frame passed on is
  // the newest, and the frames in between are counted and reported.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  runner.run();
  const auto& depth = runner.output<DepthImage>("depth");
  EXPECT_EQ(depth.frame.index, 1);
  const double dropped = metric(runner, "dropped_frames");
  EXPECT_GE(dropped, 1.0);
  EXPECT_EQ(depth.frame.timestamp_ns - first_ns,
            (static_cast<std::int64_t>(dropped) + 1) * 33'000'000);
  ASSERT_EQ(runner.warnings().size(), 1u);
  EXPECT_THAT(runner.warnings()[0], HasSubstr("'Dummy'"));
  EXPECT_THAT(runner.warnings()[0], HasSubstr("stale frame(s) dropped"));
}

TEST(OpenNi2Source, TwoSourcesShareOpenNi2AndCloseInAnyOrder) {
  // "Oz" is a second virtual device of the same test driver.
  auto first = std::make_unique<Runner>(dummy_with("policy", std::string("block")));
  auto oz = dummy_with("policy", std::string("block"));
  oz["uri"] = std::string("Oz");
  Runner second(oz);
  first->run();
  second.run();
  first.reset();  // must not shut OpenNI2 down under the second source
  second.run();
  EXPECT_EQ(second.output<DepthImage>("depth").depth.at<std::uint16_t>(0, 0), 2000);
}

}  // namespace
}  // namespace facet::openni2
