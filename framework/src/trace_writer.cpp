#include "facet/framework/trace_writer.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "facet/framework/json_writer.hpp"

namespace facet {
namespace {

// Whole microseconds, the format's unit: the viewers nest slices by comparing these, so a slice
// must not end after the next one on its thread begins merely through rounding.
std::int64_t to_us(double ms) {
  return std::llround(ms * 1000.0);
}

}  // namespace

void write_chrome_trace(std::ostream& out, const RunStats& stats, const std::string& graph_name) {
  JsonWriter json(out, 0);
  json.begin_object();
  json.key("displayTimeUnit").value("ms");
  json.key("traceEvents").begin_array();
  // Names for the process and its threads, so that the viewer labels the rows.
  json.begin_object();
  json.key("name").value("process_name");
  json.key("ph").value("M");
  json.key("pid").value(std::int64_t{1});
  json.key("args").begin_object().key("name").value("facet run " + graph_name).end_object();
  json.end_object();
  std::set<int> threads;
  for (const auto& call : stats.calls)
    threads.insert(call.thread);
  for (const int thread : threads) {
    json.begin_object();
    json.key("name").value("thread_name");
    json.key("ph").value("M");
    json.key("pid").value(std::int64_t{1});
    json.key("tid").value(std::int64_t{thread});
    json.key("args").begin_object().key("name").value("worker " + std::to_string(thread));
    json.end_object();
    json.end_object();
  }
  for (const auto& call : stats.calls) {
    const NodeStats& node = stats.nodes.at(call.node);
    const std::int64_t start_us = to_us(call.start_ms);
    json.begin_object();
    json.key("name").value(node.id);
    json.key("cat").value("stage");
    json.key("ph").value("X");
    json.key("ts").value(start_us);
    json.key("dur").value(
        std::max<std::int64_t>(0, to_us(call.start_ms + call.duration_ms) - start_us));
    json.key("pid").value(std::int64_t{1});
    json.key("tid").value(std::int64_t{call.thread});
    json.key("args").begin_object();
    json.key("frame").value(call.frame);
    json.key("stage").value(node.stage);
    json.end_object();
    json.end_object();
  }
  json.end_array();
  json.end_object();
  out << '\n';
}

}  // namespace facet
