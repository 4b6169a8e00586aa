// `facet run` end to end: the main job on the bundled frames, statistics, overrides, failures.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kTabletop = source_dir() / "graphs/tabletop.yaml";

std::size_t count_pngs(const std::filesystem::path& dir) {
  std::size_t n = 0;
  if (!std::filesystem::is_directory(dir)) return 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".png") ++n;
  }
  return n;
}

TEST(Run, TabletopOnBundledFramesWritesOneResultPerFrame) {
  TempDir out("facet-run-tabletop");
  const auto json = out.path() / "stats.json";
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) +
                              " --param output=" + shell_quote(out.path().string()) + " --json " +
                              shell_quote(json.string()) + " --profile");
  ASSERT_EQ(result.exit_code, 0) << result.out;

  const auto inputs = count_pngs(source_dir() / "data/mosd/depth");
  ASSERT_GT(inputs, 0u);
  EXPECT_EQ(count_pngs(out.path() / "labels"), inputs);

  // A label image per frame: 16-bit object ids of the input's size, with at least one object
  // (every bundled frame shows two or more) and far fewer than noise would give.
  for (const auto& entry : std::filesystem::directory_iterator(out.path() / "labels")) {
    const cv::Mat labels = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    EXPECT_EQ(labels.type(), CV_16UC1) << entry.path();
    EXPECT_EQ(labels.cols, 640);
    EXPECT_EQ(labels.rows, 480);
    double lo = 0, hi = 0;
    cv::minMaxLoc(labels, &lo, &hi);
    EXPECT_GE(hi, 1.0) << entry.path();
    EXPECT_LE(hi, 30.0) << entry.path();
    // The object list of the same frame describes the same objects.
    const auto object_file =
        out.path() / "objects" / entry.path().filename().replace_extension(".json");
    const std::string objects = read_file(object_file);
    EXPECT_NE(objects.find("\"superquadric\""), std::string::npos) << object_file;
    // Schema 2: the bundled frames' intrinsics once, and the table every object stands on as an
    // equation (every bundled frame has a table).
    for (const char* key : {"\"schema_version\": 2,", "\"camera\": {", "\"fx\": 525,",
                            "\"cy\": 239.5,", "\"width\": 640,", "\"height\": 480",
                            "\"support_plane_equation\": {", "\"offset_m\": "}) {
      EXPECT_NE(objects.find(key), std::string::npos) << key << " in " << object_file;
    }
    EXPECT_NE(objects.find("\"id\": " + std::to_string(static_cast<int>(hi))), std::string::npos)
        << object_file << "\n"
        << objects.substr(0, 400);
  }

  const std::string stats = read_file(json);
  EXPECT_NE(stats.find("\"frames\": " + std::to_string(inputs)), std::string::npos) << stats;
  for (const char* key :
       {"\"stages\"", "\"source\"", "\"median\"", "\"median_ms\"", "\"p95_ms\"", "\"total\""}) {
    EXPECT_NE(stats.find(key), std::string::npos) << key << "\n" << stats;
  }
  // --profile prints the per-stage table.
  EXPECT_NE(result.out.find("p95 ms"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("filter.median"), std::string::npos) << result.out;
}

TEST(Run, FramesOptionLimitsTheRun) {
  TempDir out("facet-run-frames");
  const auto json = out.path() / "stats.json";
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) +
                              " -q --frames 2 --param output=" + shell_quote(out.path().string()) +
                              " --json " + shell_quote(json.string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(count_pngs(out.path() / "labels"), 2u);
  EXPECT_NE(read_file(json).find("\"frames\": 2"), std::string::npos);
}

// --json lists every frame with its stem, time, each stage's time and every metric, scores
// against ground truth included, so that the worst frame is found without a rerun.
TEST(Run, JsonHoldsEachFramesTimesAndScores) {
  TempDir out("facet-run-per-frame");
  const auto json = out.path() / "stats.json";
  const auto result =
      run_cli("run " + shell_quote((source_dir() / "graphs/compare_tabletop.yaml").string()) +
              " -q --frames 3 --threads 2 --param output=" + shell_quote(out.path().string()) +
              " --json " + shell_quote(json.string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const std::string stats = read_file(json);
  const auto per_frame = stats.find("\"per_frame\": [");
  ASSERT_NE(per_frame, std::string::npos) << stats;
  const std::string frames = stats.substr(per_frame);
  // The three frames, named by their files, each with its score.
  std::size_t stems = 0;
  for (auto at = frames.find("\"stem\": \"learn"); at != std::string::npos;
       at = frames.find("\"stem\": \"learn", at + 1))
    ++stems;
  EXPECT_EQ(stems, 3u) << frames;
  std::size_t scores = 0;
  for (auto at = frames.find("\"score.f\": "); at != std::string::npos;
       at = frames.find("\"score.f\": ", at + 1)) {
    const double f = std::stod(frames.substr(at + 11));
    EXPECT_GT(f, 0.5);
    EXPECT_LE(f, 1.0);
    ++scores;
  }
  EXPECT_EQ(scores, 3u) << frames;
  EXPECT_NE(frames.find("\"stages_ms\": {"), std::string::npos);
  EXPECT_NE(frames.find("\"objects\": "), std::string::npos);
}

// A node whose required input stays empty is skipped without a word from its stage; its files
// are then silently missing. The run says so at the end.
TEST(Run, ANodeSkippedBecauseItsInputWasNeverSetIsReported) {
  TempDir out("facet-run-skipped");
  const auto graph = out.path() / "skip.yaml";
  {
    std::ofstream file(graph);
    file << "facet: 1\nname: skip\nparams: {output: x}\nnodes:\n"
            "  source: {stage: io.frames, params: {path: "
         << shell_quote((source_dir() / "data/mosd").string())
         << ", labels_dir: \"\"}}\n"
            "  labels_out: {stage: io.labels, in: {labels: source.labels}, "
            "params: {dir: \"${output}/labels\"}}\n";
  }
  const auto result = run_cli("run " + shell_quote(graph.string()) +
                              " -q --frames 3 --param output=" + shell_quote(out.path().string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("node 'labels_out' (io.labels) was skipped in 3 of 3 frame(s)"),
            std::string::npos)
      << result.out;
  EXPECT_EQ(count_pngs(out.path() / "labels"), 0u);
}

// A warning on every frame is printed for the first three frames, then counted once at the end.
TEST(Run, AWarningRepeatedOnEveryFrameIsPrintedThreeTimesThenCounted) {
  TempDir out("facet-run-repeated");
  const auto input = out.path() / "zero";
  std::filesystem::create_directories(input / "depth");
  std::filesystem::copy_file(source_dir() / "data/mosd/intrinsics.yaml", input / "intrinsics.yaml");
  for (int i = 0; i < 7; ++i) {
    std::string name = "z";
    name += std::to_string(i);
    name += ".png";
    cv::imwrite((input / "depth" / name).string(), cv::Mat(480, 640, CV_16UC1, cv::Scalar(0)));
  }
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) +
                              " -q --param input=" + shell_quote(input.string()) +
                              " --param output=" + shell_quote((out / "o").string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  std::size_t printed = 0;
  for (std::size_t at = result.out.find("no valid depth in"); at != std::string::npos;
       at = result.out.find("no valid depth in", at + 1))
    ++printed;
  EXPECT_EQ(printed, 4u) << result.out;  // frames 0, 1 and 2, and the last one in the count
  EXPECT_NE(result.out.find("warning: node 'source': 4 more like this, not printed: no valid "
                            "depth in 'z6.png'"),
            std::string::npos)
      << result.out;
}

TEST(Run, EndsBySayingWhereItWrote) {
  TempDir out("facet-run-wrote");
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) +
                              " --frames 1 --param output=" + shell_quote(out.path().string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("wrote: labels_out -> " + (out.path() / "labels").string() +
                            ", objects_out -> " + (out.path() / "objects").string()),
            std::string::npos)
      << result.out;
  const auto quiet = run_cli("run " + shell_quote(kTabletop.string()) +
                             " -q --frames 1 --param output=" + shell_quote(out.path().string()));
  EXPECT_EQ(quiet.out.find("wrote:"), std::string::npos) << quiet.out;
}

TEST(Run, SetOverridesANodeParameter) {
  TempDir out("facet-run-set");
  const auto bad = run_cli(
      "run " + shell_quote(kTabletop.string()) +
      " -q --frames 1 --set median.size=4 --param output=" + shell_quote(out.path().string()));
  EXPECT_EQ(bad.exit_code, 3) << bad.out;
  EXPECT_NE(bad.out.find("size"), std::string::npos) << bad.out;
  const auto good = run_cli(
      "run " + shell_quote(kTabletop.string()) +
      " -q --frames 1 --set median.size=3 --param output=" + shell_quote(out.path().string()));
  EXPECT_EQ(good.exit_code, 0) << good.out;
}

TEST(Run, MissingInputFolderIsARuntimeFailureNamingIt) {
  TempDir out("facet-run-missing");
  const auto missing = out.path() / "no-such-dataset";
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) +
                              " --param input=" + shell_quote(missing.string()) +
                              " --param output=" + shell_quote(out.path().string()));
  EXPECT_EQ(result.exit_code, 1) << result.out;
  EXPECT_NE(result.out.find("no-such-dataset"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("source"), std::string::npos) << result.out;
}

// Input that another source stage reads: the error names that stage and how to run it, and the
// graph it suggests exists.
TEST(Run, APcdOrOniInputNamesTheSourceStageThatReadsIt) {
  TempDir out("facet-run-other-source");
  const auto cloud = out.path() / "scan.pcd";
  const auto recording = out.path() / "take.oni";
  std::ofstream(cloud) << "# .PCD v0.7\n";
  std::ofstream(recording) << "not a recording";
  const auto pcd = run_cli("run " + shell_quote(kTabletop.string()) +
                           " --param input=" + shell_quote(cloud.string()) +
                           " --param output=" + shell_quote((out.path() / "out").string()));
  EXPECT_EQ(pcd.exit_code, 1) << pcd.out;
  for (const char* text : {"node 'source' (io.frames)", "is a PCD point cloud", "io.pcd",
                           "`facet list pcd`", "`--replace source=io.pcd --set source.path='"}) {
    EXPECT_NE(pcd.out.find(text), std::string::npos) << text << "\n" << pcd.out;
  }
  // What it suggests makes a valid graph (io.pcd is built wherever PCL is, as in every build
  // these tests run in).
  const auto swapped =
      run_cli("validate " + shell_quote(kTabletop.string()) +
              " --replace source=io.pcd --set source.path=" + shell_quote(cloud.string()));
  EXPECT_EQ(swapped.exit_code, 0) << swapped.out;
  EXPECT_EQ(pcd.out.find("not a folder"), std::string::npos) << pcd.out;
  const auto oni = run_cli("run " + shell_quote(kTabletop.string()) +
                           " --param input=" + shell_quote(recording.string()) +
                           " --param output=" + shell_quote((out.path() / "out").string()));
  EXPECT_EQ(oni.exit_code, 1) << oni.out;
  for (const char* text : {"node 'source' (io.frames)", "is an OpenNI2 recording", "io.openni2",
                           "facet run graphs/live.yaml --param uri="}) {
    EXPECT_NE(oni.out.find(text), std::string::npos) << text << "\n" << oni.out;
  }
  EXPECT_NE(read_file(source_dir() / "graphs/live.yaml").find("uri:"), std::string::npos);
}

// A full disk: the stats and the trace went unwritten with exit 0, as the check came before the
// buffer was flushed.
TEST(Run, WriteErrorsOfTheJsonAndTheTraceAreFailures) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  TempDir out("facet-run-full");
  for (const char* option : {"--json", "--trace"}) {
    const auto result =
        run_cli("run " + shell_quote(kTabletop.string()) + " -q --frames 1 --param output=" +
                shell_quote(out.path().string()) + " " + option + " /dev/full");
    EXPECT_EQ(result.exit_code, 1) << option << "\n" << result.out;
    EXPECT_NE(result.out.find("cannot write /dev/full"), std::string::npos) << result.out;
  }
}

// `--param output=` would have written to /labels, /objects and /overlay.
TEST(Run, AnEmptyOutputParamIsAnInvalidGraph) {
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) + " -q --param output=");
  EXPECT_EQ(result.exit_code, 3) << result.out;
  EXPECT_NE(result.out.find("graph parameter 'output' is empty"), std::string::npos) << result.out;
}

// Ctrl-C or SIGTERM ended the process at once: no --json, a truncated label PNG, frames with only
// some of their files. Now the frames begun are finished, the rest is not started, the
// statistics are written and the exit code says which signal it was.
TEST(Run, ASignalFinishesTheFramesBegunAndWritesTheStatistics) {
  for (const int signal : {SIGTERM, SIGINT}) {
    TempDir out("facet-run-signal");
    const auto json = out.path() / "stats.json";
    const auto log = out.path() / "log.txt";
    const std::string output = "output=" + out.path().string();
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, STDOUT_FILENO);
      ::dup2(fd, STDERR_FILENO);
      ::signal(SIGINT, SIG_DFL);  // as from a terminal, whatever this test was started with
      ::execl(FACET_CLI, FACET_CLI, "run", kTabletop.c_str(), "--param", output.c_str(), "--set",
              "source.loop=true", "--json", json.c_str(), static_cast<char*>(nullptr));
      std::_Exit(127);
    }
    // Looping over the bundled frames, the run never ends by itself: stop it once it has
    // written a few frames.
    for (int wait = 0; wait < 1200 && count_pngs(out.path() / "labels") < 3; ++wait)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_EQ(::kill(child, signal), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    const std::string printed = read_file(log);
    ASSERT_TRUE(WIFEXITED(status)) << printed;
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal) << printed;
    EXPECT_NE(printed.find(signal == SIGINT ? "stopped by SIGINT" : "stopped by SIGTERM"),
              std::string::npos)
        << printed;

    // Every label PNG is whole, nothing is left half-written, and every frame has all its files.
    for (const char* folder : {"labels", "objects", "overlay"}) {
      for (const auto& entry : std::filesystem::directory_iterator(out.path() / folder)) {
        EXPECT_EQ(entry.path().filename().string().rfind('.', 0), std::string::npos)
            << entry.path();
      }
    }
    for (const auto& entry : std::filesystem::directory_iterator(out.path() / "labels")) {
      EXPECT_FALSE(cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED).empty()) << entry.path();
      const auto stem = entry.path().stem().string();
      EXPECT_TRUE(std::filesystem::exists(out.path() / "objects" / (stem + ".json"))) << stem;
      EXPECT_TRUE(std::filesystem::exists(out.path() / "overlay" / (stem + ".png"))) << stem;
    }
    EXPECT_NE(read_file(json).find("\"frames\": "), std::string::npos) << printed;
  }
}

TEST(Run, UnknownGraphParamIsAnInvalidGraph) {
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) + " --param inptu=x");
  EXPECT_EQ(result.exit_code, 3) << result.out;
  EXPECT_NE(result.out.find("did you mean 'input'"), std::string::npos) << result.out;
}

TEST(Run, MissingPluginIsAPluginFailure) {
  TempDir dir("facet-run-plugin");
  // A plugin file that is not a shared library: it fails to load, and its stage is missing.
  std::filesystem::create_directories(dir.path() / "plugins");
  std::ofstream(dir.path() / "plugins/libfacet_broken.so") << "not an ELF file";
  const auto graph = dir.path() / "g.yaml";
  std::ofstream(graph) << "facet: 1\nname: g\nnodes:\n  cam: {stage: io.camera}\n";
  const auto result = run_cli("run " + shell_quote(graph.string()) + " --plugin-path " +
                              shell_quote((dir.path() / "plugins").string()));
  EXPECT_EQ(result.exit_code, 4) << result.out;
  EXPECT_NE(result.out.find("libfacet_broken.so"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace facet::test

namespace facet::test {
namespace {

TEST(Run, FacesGraphWritesPatchesAndEdgesPerFrame) {
  TempDir out("facet-run-faces");
  const auto result = run_cli("run " + shell_quote((source_dir() / "graphs/faces.yaml").string()) +
                              " -q --param output=" + shell_quote(out.path().string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto inputs = count_pngs(source_dir() / "data/mosd/depth");
  ASSERT_EQ(count_pngs(out.path() / "patches"), inputs);
  ASSERT_EQ(count_pngs(out.path() / "edges"), inputs);
  for (const auto& entry : std::filesystem::directory_iterator(out.path() / "patches")) {
    const cv::Mat patches = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(patches.type(), CV_16UC1) << entry.path();
    double lo = 0, hi = 0;
    cv::minMaxLoc(patches, &lo, &hi);
    // A table and a few box faces: more than a handful of patches, far fewer than noise would give.
    EXPECT_GE(hi, 3.0) << entry.path();
    EXPECT_LE(hi, 200.0) << entry.path();
    const cv::Mat edges =
        cv::imread((out.path() / "edges" / entry.path().filename()).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(edges.type(), CV_8UC1);
    // A binary mask: only 0 and 255.
    EXPECT_EQ(cv::countNonZero(edges == 0) + cv::countNonZero(edges == 255),
              edges.rows * edges.cols);
  }
}

TEST(Run, EveryVariantOfTheAbGraphsIsValid) {
  for (const auto& [graph, variants] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"ab_normals", {"cross_r1", "cross_r2", "pca3", "pca5", "integral"}},
           {"ab_edges", {"max1", "max3", "avg1", "avg3"}}}) {
    for (const auto& variant : variants) {
      const auto result = run_cli(
          "validate " + shell_quote((source_dir() / "graphs" / (graph + ".yaml")).string()) +
          " --variant " + variant);
      EXPECT_EQ(result.exit_code, 0) << graph << " " << variant << "\n" << result.out;
    }
  }
}

#if defined(FACET_HAVE_VIEW)
// --view adds a window over the graph's depth input and labels output without editing the graph;
// without a display the run goes on and says so once.
TEST(Run, ViewWatchesTheRunInAWindowOfItsOwn) {
  TempDir out("facet-run-view");
  const std::string no_display = "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM";
  const auto result = run_cli("run " + shell_quote(kTabletop.string()) + " --view --frames 2" +
                                  " --param output=" + shell_quote(out.path().string()),
                              no_display);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("io.view shows nothing: no display"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("io.view shows nothing"), result.out.rfind("io.view shows nothing"))
      << result.out;
  EXPECT_TRUE(std::filesystem::exists(out / "labels" / "learn0.png"));

  // A graph that does not say where its depth and labels are cannot be watched this way.
  const auto faces =
      run_cli("run " + shell_quote((source_dir() / "graphs/faces.yaml").string()) +
                  " --view --frames 1 --param output=" + shell_quote((out / "faces").string()),
              no_display);
  EXPECT_EQ(faces.exit_code, 3) << faces.out;
  EXPECT_NE(faces.out.find("--view shows the graph's depth and labels"), std::string::npos)
      << faces.out;
}
#endif

// Every graph shipped in graphs/ validates against the bundled plugins.
TEST(Run, EveryShippedGraphIsValid) {
  int graphs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "graphs")) {
    if (entry.path().extension() != ".yaml") continue;
#if !defined(FACET_HAVE_OPENNI2) || !defined(FACET_HAVE_VIEW)
    // live.yaml needs the optional openni2 and view plugins, record_oni.yaml the openni2 one
    // (io.oni), and so does the openni2 variant of ros2_camera.yaml: not built without OpenNI2
    // or OpenCV's highgui, nor in ThreadSanitizer builds.
    if (entry.path().filename() == "live.yaml" || entry.path().filename() == "record_oni.yaml" ||
        entry.path().filename() == "ros2_camera.yaml")
      continue;
#endif
#if !defined(FACET_HAVE_ROS2)
    // ros2_camera.yaml and ros2_tabletop.yaml need the optional ros2 plugin (Cyclone DDS).
    if (entry.path().filename().string().starts_with("ros2_")) continue;
#endif
    ++graphs;
    const auto result = run_cli("validate " + shell_quote(entry.path().string()));
    EXPECT_EQ(result.exit_code, 0) << entry.path().filename() << "\n" << result.out;
  }
  EXPECT_GE(graphs, 9);
}

}  // namespace
}  // namespace facet::test
