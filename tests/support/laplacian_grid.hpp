#pragma once
// A small symmetric positive-definite matrix with the sparsity of a 2-D mesh, for the linear
// algebra's tests (SparseCholesky, UpdatableFactor).

#include <span>
#include <vector>

#include "solver/lac/csc_pattern.hpp"

namespace saasgaps::testing {

/// The 5-point Laplacian of a side x side grid plus `shift` on the diagonal: symmetric positive
/// definite, with supernodes of several columns under nested dissection.
struct Grid {
  CscPattern pattern;
  std::vector<double> values;

  Grid(Index side, double shift) {
    const Index n = side * side;
    std::vector<std::vector<Index>> cliques;
    for (Index y = 0; y < side; ++y) {
      for (Index x = 0; x < side; ++x) {
        const Index k = y * side + x;
        if (x + 1 < side) cliques.push_back({k, k + 1});
        if (y + 1 < side) cliques.push_back({k, k + side});
      }
    }
    pattern = CscPattern::from_cliques(n, cliques.size(), [&](std::size_t c) { return std::span<const Index>(cliques[c]); });
    values.assign(static_cast<std::size_t>(pattern.nnz()), 0.0);
    for (Index j = 0; j < n; ++j) {
      for (Index p = pattern.colptr[j]; p < pattern.colptr[j + 1]; ++p) {
        values[p] = pattern.rowind[p] == j ? 4.0 + shift : -1.0;
      }
    }
  }
  [[nodiscard]] Index n() const { return pattern.n; }
};

}  // namespace saasgaps::testing
