// Disjoint sets with path halving and union by size (or by smallest root):
// the grouping step of block cutting (faces merged into blocks, vertices
// merged into nodes), of the fracture-network component analysis and of the
// flow networks' node merging and component numbering.
#pragma once

#include <numeric>
#include <utility>
#include <vector>

namespace fissure {

class UnionFind {
 public:
  explicit UnionFind(int n = 0) { reset(n); }

  void reset(int n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0);
    size_.assign(n, 1);
  }

  int size() const { return static_cast<int>(parent_.size()); }

  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  /// Joins the sets of a and b; returns the new root (the root of the larger
  /// set, or of a's set on a tie), or -1 when they were already one set.
  int unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return -1;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return a;
  }

  /// Joins b's set into a's set, keeping a's root as the root (for callers
  /// that keep per-root data and want to choose which root survives).
  void attach(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    parent_[b] = a;
    size_[a] += size_[b];
  }

  /// Joins the sets of a and b keeping the smaller root as the root, so that
  /// (when every join uses it) a set's root is its smallest element: numbering
  /// by first root met then follows the input order (the fracture networks'
  /// node and component numbers). Returns false when already one set.
  bool unite_to_smallest(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }

  int set_size(int x) { return size_[find(x)]; }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

}  // namespace fissure
