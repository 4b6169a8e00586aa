#pragma once
// Disjoint sets (union-find) over the indices 0..n-1, the one every stage family uses: surface
// regions over pixel runs, Euclidean blobs over pixels, label pieces, and the patch groups of the
// object stages.
//
// The root of a set is always its smallest index. Elements numbered in raster order (pixels,
// runs, patches by id) therefore give sets whose roots come in raster order of their first
// element, so ids handed out over the roots in index order need no sorting, and the result does
// not depend on the order of the unions. Finding uses path halving; unions are by index, not by
// rank, which keeps the smallest-root rule (the trees stay shallow on raster scans, where an
// element is mostly joined to a recent neighbour).

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace facet::algo {

class DisjointSets {
 public:
  // `count` elements, each a set of its own. Keeps the memory of earlier frames.
  void reset(std::size_t count) {
    parent_.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      parent_[i] = static_cast<std::int32_t>(i);
  }
  // `count` elements whose sets are made one by one with make(): for a mask of which only some
  // elements take part (their sets are never looked at otherwise).
  void reset_unmade(std::size_t count) { parent_.resize(count); }
  void make(std::int32_t i) { parent_[static_cast<std::size_t>(i)] = i; }

  std::size_t size() const { return parent_.size(); }

  // The root of i's set.
  std::int32_t find(std::int32_t i) {
    while (parent(i) != i) {
      parent_[static_cast<std::size_t>(i)] = parent(parent(i));  // path halving
      i = parent(i);
    }
    return i;
  }

  // Joins the sets of a and b under the smaller root. Returns whether they were two sets.
  bool unite(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (b < a) std::swap(a, b);
    parent_[static_cast<std::size_t>(b)] = a;
    return true;
  }

  // Once every union is done, called for the elements in ascending order: points i straight at
  // its root and returns the root. A parent always has a smaller index than its child, so it is
  // already flat when the child is visited.
  std::int32_t flatten(std::int32_t i) {
    parent_[static_cast<std::size_t>(i)] = parent(parent(i));
    return parent(i);
  }

  // i's parent: after flatten() of i, its root.
  std::int32_t parent(std::int32_t i) const { return parent_[static_cast<std::size_t>(i)]; }
  bool is_root(std::int32_t i) const { return parent(i) == i; }

 private:
  std::vector<std::int32_t> parent_;
};

}  // namespace facet::algo
