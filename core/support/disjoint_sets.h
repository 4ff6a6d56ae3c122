#pragma once
// Disjoint sets (union-find) over indices 0 … n−1, with path halving or compression.
#include <algorithm>
#include <numeric>
#include <vector>

namespace gps {

/// Union-find whose root is the lowest index of each set.
struct LowestRootSets {
  std::vector<int> parent;
  explicit LowestRootSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b);
  }
};

/// Union-find over faces, each with its parity: whether it is flipped against its set's root for every
/// pair of faces joined so far to run their shared edge in opposite directions.
struct ParitySets {
  std::vector<int> parent;
  std::vector<char> parity;  // against the parent
  explicit ParitySets(size_t n) : parent(n), parity(n, 0) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x, char& parity_to_root) {
    int root = x;
    char p = 0;
    while (parent[size_t(root)] != root) {
      p ^= parity[size_t(root)];
      root = parent[size_t(root)];
    }
    parity_to_root = p;
    while (x != root) {  // the path compressed, each node's parity now against the root
      const int up = parent[size_t(x)];
      const char own = parity[size_t(x)];
      parent[size_t(x)] = root;
      parity[size_t(x)] = p;
      p ^= own;
      x = up;
    }
    return root;
  }
  int find(int x) {
    char p;
    return find(x, p);
  }
  /// Joins a and b so that one is flipped against the other exactly where `flipped`.
  void unite(int a, int b, bool flipped) {
    char pa = 0, pb = 0;
    a = find(a, pa);
    b = find(b, pb);
    if (a == b) return;
    parent[size_t(std::max(a, b))] = std::min(a, b);
    parity[size_t(std::max(a, b))] = char(pa ^ pb ^ char(flipped));
  }
};

}  // namespace gps
