#include "graph_order.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/depth_first_search.hpp>
#include <functional>
#include <queue>

namespace facet::detail {
namespace {

struct EdgeInfo {
  std::size_t dependency = 0;  // index into the caller's edges
};

// vecS for vertices and out-edges keeps file order in vertex ids and edge iteration, which is
// what makes both the cycle report and the order deterministic.
using DependencyGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS,
                                              boost::no_property, EdgeInfo>;
using Vertex = boost::graph_traits<DependencyGraph>::vertex_descriptor;
using Edge = boost::graph_traits<DependencyGraph>::edge_descriptor;

DependencyGraph build(std::size_t node_count, const std::vector<Dependency>& edges) {
  DependencyGraph graph(node_count);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    boost::add_edge(edges[i].from, edges[i].to, EdgeInfo{i}, graph);
  }
  return graph;
}

// A back edge u -> v closes a cycle: v is on the DFS stack, and the tree path from v down to u
// is the rest of it. BGL copies visitors, so the state lives outside.
class CycleRecorder : public boost::default_dfs_visitor {
 public:
  CycleRecorder(std::vector<Vertex>& parent, std::vector<std::size_t>& back_edges)
      : parent_(&parent), back_edges_(&back_edges) {}

  void tree_edge(Edge edge, const DependencyGraph& graph) const {
    (*parent_)[boost::target(edge, graph)] = boost::source(edge, graph);
  }
  void back_edge(Edge edge, const DependencyGraph& graph) const {
    back_edges_->push_back(graph[edge].dependency);
  }

 private:
  std::vector<Vertex>* parent_;
  std::vector<std::size_t>* back_edges_;
};

}  // namespace

std::vector<Cycle> find_cycles(std::size_t node_count, const std::vector<Dependency>& edges) {
  const DependencyGraph graph = build(node_count, edges);
  std::vector<Vertex> parent(node_count);
  for (std::size_t i = 0; i < node_count; ++i)
    parent[i] = i;
  std::vector<std::size_t> back_edges;
  boost::depth_first_search(graph, boost::visitor(CycleRecorder(parent, back_edges)));

  std::vector<Cycle> cycles;
  for (const std::size_t index : back_edges) {
    const Dependency& closing = edges[index];
    // Walk up from the edge's source to its target, then reverse into reading order.
    std::vector<std::size_t> path{closing.to};
    for (Vertex v = closing.from; v != closing.to; v = parent[v])
      path.push_back(v);
    path.push_back(closing.to);
    std::reverse(path.begin() + 1, path.end() - 1);
    cycles.push_back({std::move(path), closing.where});
  }
  return cycles;
}

std::vector<std::size_t> topological_order(std::size_t node_count,
                                           const std::vector<Dependency>& edges) {
  // Kahn's algorithm with a min-queue over file positions rather than boost::topological_sort,
  // whose reverse-finish order is deterministic but shuffles independent nodes (a sink can come
  // before a later source); the file order is what users expect in `facet validate` and traces.
  const DependencyGraph graph = build(node_count, edges);
  std::vector<std::size_t> waiting(node_count);
  std::priority_queue<std::size_t, std::vector<std::size_t>, std::greater<>> ready;
  for (std::size_t v = 0; v < node_count; ++v) {
    waiting[v] = boost::in_degree(v, graph);
    if (waiting[v] == 0) ready.push(v);
  }
  std::vector<std::size_t> order;
  std::vector<bool> placed(node_count, false);
  while (!ready.empty()) {
    const std::size_t v = ready.top();
    ready.pop();
    order.push_back(v);
    placed[v] = true;
    for (const auto edge : boost::make_iterator_range(boost::out_edges(v, graph))) {
      const std::size_t next = boost::target(edge, graph);
      if (--waiting[next] == 0) ready.push(next);
    }
  }
  for (std::size_t v = 0; v < node_count; ++v) {
    if (!placed[v]) order.push_back(v);
  }
  return order;
}

}  // namespace facet::detail
