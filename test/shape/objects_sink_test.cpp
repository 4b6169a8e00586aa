// io.objects: one JSON file per frame with every field of the object list, written the same way
// every time; write errors name the file.
#include "io/objects_sink.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "facet/testing/stage_runner.hpp"
#include "temp_dir.hpp"

namespace facet::io {
namespace {

ObjectList sample_list() {
  ObjectList list;
  list.frame.stem = "learn \"7\"";
  list.frame.index = 7;
  list.frame.timestamp_ns = 233333333;
  list.camera = {.fx = 525.0, .fy = 526.5, .cx = 319.5, .cy = 239.5, .width = 640, .height = 480};
  ObjectModel object;
  object.id = 3;
  object.pixel_count = 4200;
  object.centroid_m = {0.01, -0.02, 0.9};
  object.bounds_m.extend(Eigen::Vector3d(-0.05, -0.06, 0.85));
  object.bounds_m.extend(Eigen::Vector3d(0.07, 0.02, 0.95));
  object.box.pose.translation() = Eigen::Vector3d(0.01, -0.02, 0.88);
  object.box.half_extents_m = {0.06, 0.035, 0.01};
  object.box.residual_m = 0.004;
  object.support_plane = 1;
  object.support_normal = {0.0, -0.6, -0.8};  // the table, facing up and towards the camera
  object.support_offset_m = 0.75;
  object.superquadric.valid = true;
  object.superquadric.size_m = {0.06, 0.035, 0.05};
  object.superquadric.epsilon1 = 0.1;
  object.superquadric.epsilon2 = 0.25;
  object.superquadric.residual = 0.0005;
  object.superquadric.pose.translation() = Eigen::Vector3d(0.01, -0.02, 0.92);
  object.grasp = GraspPrototype::precision;
  list.objects.push_back(object);
  ObjectModel empty;  // an object without points: no bounds, no superquadric
  empty.id = 4;
  empty.pixel_count = 2;
  list.objects.push_back(empty);
  return list;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Brackets balance outside strings, and strings are closed: enough to catch broken output.
bool brackets_balance(const std::string& text) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    if (c == '{' || c == '[') ++depth;
    if (c == '}' || c == ']') --depth;
    if (depth < 0) return false;
  }
  return depth == 0 && !in_string;
}

TEST(ObjectsSink, WritesEveryFieldDeterministically) {
  const test::TempDir dir;
  testing::StageRunner<ObjectsSink> runner({{"dir", dir.path().string()}});
  runner.set_input("objects", Packet::make(sample_list()));
  runner.run();
  const std::filesystem::path file = dir / "learn \"7\".json";
  ASSERT_TRUE(std::filesystem::exists(file));
  const std::string text = read_text(file);
  EXPECT_TRUE(brackets_balance(text));
  for (const char* expected : {"{\n  \"schema_version\": 2,\n  \"frame\": {",
                               "\"stem\": \"learn \\\"7\\\"\"",
                               "\"index\": 7",
                               "\"timestamp_ns\": 233333333",
                               "\"id\": 3",
                               "\"pixel_count\": 4200",
                               "\"centroid_m\": [0.01, -0.02, 0.9]",
                               "\"min\": [-0.05, -0.06, 0.85]",
                               "\"max\": [0.07, 0.02, 0.95]",
                               "\"half_extents_m\": [0.06, 0.035, 0.01]",
                               "\"quaternion_wxyz\": [1, 0, 0, 0]",
                               "\"rotation\": [",
                               "\"support_plane\": 1,\n"
                               "      \"support_plane_equation\": {\n"
                               "        \"normal\": [0, -0.6, -0.8],\n"
                               "        \"offset_m\": 0.75\n"
                               "      },",
                               "\"size_m\": [0.06, 0.035, 0.05]",
                               "\"epsilon1\": 0.1",
                               "\"epsilon2\": 0.25",
                               "\"residual_m\": 0.0005",
                               "\"grasp\": \"precision\"",
                               "\"id\": 4",
                               "\"bounds_m\": null",
                               "\"support_plane\": 0,\n      \"support_plane_equation\": null",
                               "\"superquadric\": null",
                               "\"grasp\": \"none\""}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  }
  EXPECT_EQ(text, objects_to_json(sample_list()));
}

// The intrinsics come once per file, after the frame and before the objects, so that a grasp
// planner can project the objects into the image without the dataset's intrinsics.yaml.
TEST(ObjectsSink, WritesTheCameraIntrinsicsOncePerFile) {
  const std::string text = objects_to_json(sample_list());
  const std::string camera =
      "  \"camera\": {\n"
      "    \"fx\": 525,\n"
      "    \"fy\": 526.5,\n"
      "    \"cx\": 319.5,\n"
      "    \"cy\": 239.5,\n"
      "    \"width\": 640,\n"
      "    \"height\": 480\n"
      "  },\n"
      "  \"objects\": [";
  const std::size_t at = text.find(camera);
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_GT(at, text.find("\"timestamp_ns\""));
  EXPECT_EQ(text.find("\"camera\"", at + camera.size()), std::string::npos) << "written twice:\n"
                                                                            << text;
}

TEST(ObjectsSink, CameraIsNullWithoutIntrinsics) {
  ObjectList list;  // made by a program that set no camera
  const std::string text = objects_to_json(list);
  EXPECT_NE(text.find("\"camera\": null,\n  \"objects\": ["), std::string::npos) << text;
  EXPECT_TRUE(brackets_balance(text));
}

TEST(ObjectsSink, EmptyListAndMissingStem) {
  const test::TempDir dir;
  ObjectList list;
  list.frame.index = 12;
  testing::StageRunner<ObjectsSink> runner({{"dir", dir.path().string()}});
  runner.set_input("objects", Packet::make(list));
  runner.run();
  const std::string text = read_text(dir / "frame_000012.json");
  EXPECT_TRUE(brackets_balance(text));
  EXPECT_NE(text.find("\"objects\": [\n  ]"), std::string::npos) << text;
}

TEST(ObjectsSink, WriteErrorNamesTheFile) {
  const test::TempDir dir;
  // A folder where the file should go makes the write fail.
  std::filesystem::create_directories(dir / "blocked.json");
  ObjectList list;
  list.frame.stem = "blocked";
  testing::StageRunner<ObjectsSink> runner({{"dir", dir.path().string()}});
  runner.set_input("objects", Packet::make(list));
  try {
    runner.run();
    FAIL() << "expected a StageError";
  } catch (const StageError& error) {
    EXPECT_NE(std::string(error.what()).find("blocked.json"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace facet::io
