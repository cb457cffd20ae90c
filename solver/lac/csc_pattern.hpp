#pragma once
/// Upper-triangular compressed-column sparsity pattern of a symmetric matrix. Linear algebra only:
/// it knows nothing of elements or nodes, just of "cliques" (index sets coupled to each other).

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace saasgaps {

using Index = std::int64_t;  ///< SuiteSparse_long

struct CscPattern {
  Index n = 0;
  std::vector<Index> colptr;  ///< n + 1 column starts
  std::vector<Index> rowind;  ///< row indices, ascending within each column, row <= column

  [[nodiscard]] Index nnz() const { return colptr.empty() ? 0 : colptr.back(); }

  /// Position of entry (i, j) (either order) in rowind / the value array, or -1 when absent.
  [[nodiscard]] Index find(Index i, Index j) const;

  /// The pattern of a sum of dense blocks, clique c coupling every index in cliques(c) with every
  /// other, plus the whole diagonal. Negative indices are skipped (eliminated unknowns).
  /// O(nnz * clique size) time, no triplets.
  static CscPattern from_cliques(Index n, std::size_t clique_count,
                                 const std::function<std::span<const Index>(std::size_t)>& cliques);
};

/// Index sets ("cliques") in CSR layout, clique c = members[start[c] .. start[c + 1]): the couplings a
/// pattern must hold beyond elements, e.g. constraint rows of any width.
struct Cliques {
  std::vector<Index> start{0};
  std::vector<Index> members;

  [[nodiscard]] std::size_t size() const { return start.size() - 1; }
  [[nodiscard]] std::span<const Index> operator[](std::size_t c) const {
    return {members.data() + start[c], static_cast<std::size_t>(start[c + 1] - start[c])};
  }
  void add(std::span<const Index> clique) {
    members.insert(members.end(), clique.begin(), clique.end());
    start.push_back(static_cast<Index>(members.size()));
  }
};

/// Indices grouped (groups[i] = the group of index i, 0 .. count-1), members listed per group in
/// ascending order, CSR layout: members[start[g] .. start[g + 1]).
struct IndexGroups {
  std::vector<Index> start;
  std::vector<Index> members;
  [[nodiscard]] Index count() const { return static_cast<Index>(start.size()) - 1; }
  static IndexGroups of(std::span<const Index> groups);
};

/// The quotient graph: one vertex per group, (g, h) coupled when some index of g couples to some
/// index of h in `pattern`; upper triangle with the diagonal left out (a graph for an ordering).
CscPattern group_pattern(const CscPattern& pattern, std::span<const Index> groups, const IndexGroups& members);

/// An ordering of the groups expanded to their members (a group's members stay together, in order).
std::vector<Index> expand(std::span<const Index> group_order, const IndexGroups& members);

}  // namespace saasgaps
