#include "partition/graph_cut.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace facet::partition {

namespace {

// An edge between two distinct nodes of 0 .. node_count - 1; others are ignored.
bool joins_two_nodes(const GraphEdge& edge, std::size_t node_count) {
  return edge.a != edge.b && edge.a >= 0 && edge.b >= 0 &&
         static_cast<std::size_t>(edge.a) < node_count &&
         static_cast<std::size_t>(edge.b) < node_count;
}

}  // namespace

const std::vector<std::int32_t>& GraphCut::groups(std::int32_t node_count,
                                                  std::span<const GraphEdge> edges,
                                                  const CutRule& rule, const StepPairs& steps) {
  const auto n = static_cast<std::size_t>(std::max(node_count, 0));
  groups_joined_.reset(n);
  neighbours_.assign(n, {});
  local_.assign(n, -1);
  for (const GraphEdge& edge : edges) {
    if (!joins_two_nodes(edge, n)) continue;
    neighbours_[static_cast<std::size_t>(edge.a)].push_back(edge.b);
    neighbours_[static_cast<std::size_t>(edge.b)].push_back(edge.a);
    groups_joined_.unite(edge.a, edge.b);
  }
  for (auto& list : neighbours_) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  // Connected components, members ascending.
  std::vector<std::vector<std::int32_t>> components;
  std::vector<std::int32_t> component_of_root(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const auto root = static_cast<std::size_t>(groups_joined_.find(static_cast<std::int32_t>(i)));
    if (component_of_root[root] < 0) {
      component_of_root[root] = static_cast<std::int32_t>(components.size());
      components.emplace_back();
    }
    components[static_cast<std::size_t>(component_of_root[root])].push_back(
        static_cast<std::int32_t>(i));
  }
  group_.assign(n, -1);
  next_group_ = 0;
  cuts_ = 0;
  for (auto& members : components) {
    split(std::move(members), rule);
  }
  step_separations_ = 0;
  if (!steps.empty()) separate_steps(edges, steps);
  // Renumber in order of each group's first node, whatever order the splits produced them in.
  std::vector<std::int32_t> renumber(static_cast<std::size_t>(next_group_), -1);
  std::int32_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t& id = renumber[static_cast<std::size_t>(group_[i])];
    if (id < 0) id = count++;
    group_[i] = id;
  }
  return group_;
}

void GraphCut::split(std::vector<std::int32_t> members, const CutRule& rule) {
  // Fewer than four nodes cannot be cut below ½: a pair costs 1, a path of three ¾.
  const auto size = static_cast<std::int32_t>(members.size());
  std::vector<char> side;
  if (rule.enabled && size >= 4 && size <= rule.max_nodes &&
      minimum_cut(members, side) < rule.max_cost) {
    // Each side of a minimum cut is connected (else a cheaper cut would exist); the two are
    // split in turn, with degrees recounted within each.
    std::vector<std::int32_t> first;
    std::vector<std::int32_t> second;
    for (std::size_t k = 0; k < members.size(); ++k) {
      (side[k] != 0 ? first : second).push_back(members[k]);
    }
    if (!rule.needs_cycles || (has_cycle(first) && has_cycle(second))) {
      ++cuts_;
      split(std::move(first), rule);
      split(std::move(second), rule);
      return;
    }
  }
  for (const std::int32_t node : members)
    group_[static_cast<std::size_t>(node)] = next_group_;
  ++next_group_;
}

void GraphCut::separate_steps(std::span<const GraphEdge> edges, const StepPairs& steps) {
  std::vector<std::int32_t> joined_groups;
  for (const auto& [a, b] : steps) {
    const std::int32_t group = group_[static_cast<std::size_t>(a)];
    if (group == group_[static_cast<std::size_t>(b)]) joined_groups.push_back(group);
  }
  std::sort(joined_groups.begin(), joined_groups.end());
  joined_groups.erase(std::unique(joined_groups.begin(), joined_groups.end()), joined_groups.end());
  if (joined_groups.empty()) return;
  const auto in_joined_group = [&](std::int32_t node) {
    return std::binary_search(joined_groups.begin(), joined_groups.end(),
                              group_[static_cast<std::size_t>(node)]);
  };
  // The edges of those groups, most contact first; ties in node order, so the result is
  // deterministic. An edge within a group has both ends in it.
  std::vector<GraphEdge> order;
  for (const GraphEdge& edge : edges) {
    if (joins_two_nodes(edge, group_.size()) && in_joined_group(edge.a) &&
        group_[static_cast<std::size_t>(edge.a)] == group_[static_cast<std::size_t>(edge.b)]) {
      order.push_back(edge);
    }
  }
  std::sort(order.begin(), order.end(), [](const GraphEdge& x, const GraphEdge& y) {
    if (x.contact_px != y.contact_px) return x.contact_px > y.contact_px;
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  regrouped_.reset(group_.size());
  for (const GraphEdge& edge : order) {
    const std::int32_t root_a = regrouped_.find(edge.a);
    const std::int32_t root_b = regrouped_.find(edge.b);
    if (root_a == root_b) continue;
    const bool joins_a_step = std::any_of(steps.begin(), steps.end(), [&](const auto& step) {
      const std::int32_t first = regrouped_.find(step.first);
      const std::int32_t second = regrouped_.find(step.second);
      return (first == root_a && second == root_b) || (first == root_b && second == root_a);
    });
    if (!joins_a_step) regrouped_.unite(root_a, root_b);
  }
  // Each group's part that holds its first node keeps the group's id; the others get new ones.
  std::vector<std::int32_t> id_of_root(group_.size(), -1);
  std::vector<char> group_taken(static_cast<std::size_t>(next_group_), 0);
  for (std::size_t i = 0; i < group_.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    if (!in_joined_group(node)) continue;
    const auto root = static_cast<std::size_t>(regrouped_.find(node));
    if (id_of_root[root] < 0) {
      const auto group = static_cast<std::size_t>(group_[i]);
      if (group_taken[group] == 0) {
        group_taken[group] = 1;
        id_of_root[root] = group_[i];
      } else {
        id_of_root[root] = next_group_++;
      }
    }
  }
  step_separations_ = static_cast<std::int64_t>(joined_groups.size());
  for (std::size_t i = 0; i < group_.size(); ++i) {
    const auto root = static_cast<std::size_t>(regrouped_.find(static_cast<std::int32_t>(i)));
    if (id_of_root[root] >= 0) group_[i] = id_of_root[root];
  }
}

bool GraphCut::has_cycle(const std::vector<std::int32_t>& members) {
  for (std::size_t k = 0; k < members.size(); ++k)
    local_[static_cast<std::size_t>(members[k])] = static_cast<std::int32_t>(k);
  std::size_t edge_ends = 0;
  for (const std::int32_t node : members) {
    for (const std::int32_t j : neighbours_[static_cast<std::size_t>(node)]) {
      if (local_[static_cast<std::size_t>(j)] >= 0) ++edge_ends;
    }
  }
  for (const std::int32_t node : members)
    local_[static_cast<std::size_t>(node)] = -1;
  // A connected graph with as many edges as nodes is not a tree.
  return edge_ends / 2 >= members.size();
}

double GraphCut::minimum_cut(const std::vector<std::int32_t>& members, std::vector<char>& side) {
  const std::size_t n = members.size();
  for (std::size_t k = 0; k < n; ++k)
    local_[static_cast<std::size_t>(members[k])] = static_cast<std::int32_t>(k);
  // Degrees within the group, then the edge costs as a dense matrix (groups are small).
  std::vector<double> degree(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    for (const std::int32_t j : neighbours_[static_cast<std::size_t>(members[k])]) {
      if (local_[static_cast<std::size_t>(j)] >= 0) degree[k] += 1.0;
    }
  }
  std::vector<double> weight(n * n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    for (const std::int32_t j : neighbours_[static_cast<std::size_t>(members[k])]) {
      const std::int32_t l = local_[static_cast<std::size_t>(j)];
      if (l < 0) continue;
      weight[k * n + static_cast<std::size_t>(l)] =
          0.5 * (1.0 / degree[k] + 1.0 / degree[static_cast<std::size_t>(l)]);
    }
  }
  for (const std::int32_t node : members)
    local_[static_cast<std::size_t>(node)] = -1;

  // Stoer-Wagner: n - 1 phases; each grows a maximum adjacency order and merges its last two
  // vertices; the cheapest "cut of the phase" is the minimum cut. Ties go to the lower index,
  // so the result is deterministic.
  std::vector<std::vector<std::int32_t>> merged(n);
  for (std::size_t k = 0; k < n; ++k)
    merged[k] = {static_cast<std::int32_t>(k)};
  std::vector<char> alive(n, 1);
  std::vector<char> added(n, 0);
  std::vector<double> key(n, 0.0);
  double best = std::numeric_limits<double>::infinity();
  std::vector<std::int32_t> best_side;
  for (std::size_t phase = 0; phase + 1 < n; ++phase) {
    std::fill(added.begin(), added.end(), 0);
    std::fill(key.begin(), key.end(), 0.0);
    std::size_t previous = n;
    std::size_t last = n;
    const std::size_t remaining = n - phase;
    for (std::size_t step = 0; step < remaining; ++step) {
      std::size_t pick = n;
      for (std::size_t v = 0; v < n; ++v) {
        if (alive[v] == 0 || added[v] != 0) continue;
        if (pick == n || key[v] > key[pick]) pick = v;
      }
      added[pick] = 1;
      previous = last;
      last = pick;
      if (step + 1 == remaining) break;
      for (std::size_t v = 0; v < n; ++v) {
        if (alive[v] != 0 && added[v] == 0) key[v] += weight[pick * n + v];
      }
    }
    if (key[last] < best) {
      best = key[last];
      best_side = merged[last];
    }
    // Merge `last` into `previous`.
    for (std::size_t v = 0; v < n; ++v) {
      weight[previous * n + v] += weight[last * n + v];
      weight[v * n + previous] = weight[previous * n + v];
    }
    weight[previous * n + previous] = 0.0;
    merged[previous].insert(merged[previous].end(), merged[last].begin(), merged[last].end());
    alive[last] = 0;
  }
  side.assign(n, 0);
  for (const std::int32_t k : best_side)
    side[static_cast<std::size_t>(k)] = 1;
  return best;
}

}  // namespace facet::partition
