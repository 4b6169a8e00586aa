// `facet run` with several threads: the executor options, the throughput in the reports and the
// Chrome trace.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

const std::filesystem::path kTabletop = source_dir() / "graphs/tabletop.yaml";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

// The "tid" of every slice in a trace written by facet (one event per line is not guaranteed, so
// the numbers are read after each key).
std::set<std::string> threads_in(const std::string& trace) {
  std::set<std::string> threads;
  const std::string key = "\"tid\":";
  for (auto at = trace.find(key); at != std::string::npos; at = trace.find(key, at + 1)) {
    const auto begin = at + key.size();
    threads.insert(trace.substr(begin, trace.find_first_not_of("0123456789", begin) - begin));
  }
  return threads;
}

TEST(RunParallel, TwoThreadsWriteATraceAndReportThroughput) {
  TempDir out("facet-run-parallel");
  const auto json = out.path() / "stats.json";
  const auto trace = out.path() / "trace.json";
  const auto result = run_cli(
      "run " + shell_quote(kTabletop.string()) + " --threads 2 --in-flight 3" +
      " --param output=" + shell_quote((out.path() / "o").string()) + " --json " +
      shell_quote(json.string()) + " --trace " + shell_quote(trace.string()) + " --profile");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("frames/s"), std::string::npos) << result.out;
  const std::string stats = read_file(json);
  for (const char* key : {"\"throughput_fps\"", "\"wall_ms\"", "\"dropped\": 0"})
    EXPECT_NE(stats.find(key), std::string::npos) << key << "\n" << stats;

  // One slice per stage call: 13 nodes on each of the 6 bundled frames, and the source's call
  // that ended the stream.
  const std::string text = read_file(trace);
  EXPECT_NE(text.find("\"traceEvents\""), std::string::npos);
  EXPECT_EQ(count(text, "\"ph\":\"X\""), 13u * 6u + 1u) << text.substr(0, 400);
  EXPECT_EQ(count(text, "\"name\":\"shapes\""), 6u);
  for (const auto& thread : threads_in(text))
    EXPECT_TRUE(thread == "0" || thread == "1") << thread;
}

TEST(RunParallel, SequentialExecutorRunsEverythingOnOneThread) {
  TempDir out("facet-run-sequential");
  const auto trace = out.path() / "trace.json";
  const auto result =
      run_cli("run " + shell_quote(kTabletop.string()) +
              " -q --executor sequential --threads 2 --frames 2 --param output=" +
              shell_quote((out.path() / "o").string()) + " --trace " + shell_quote(trace.string()));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(threads_in(read_file(trace)), (std::set<std::string>{"0"}));
}

TEST(RunParallel, UnknownSourcePolicyIsAUsageError) {
  const auto result =
      run_cli("run " + shell_quote(kTabletop.string()) + " --source-policy newest --frames 1");
  EXPECT_EQ(result.exit_code, 2) << result.out;
  EXPECT_NE(result.out.find("--source-policy"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace facet::test
