#pragma once
/// A few sparse columns over the unknowns: the columns w of a low-rank update W W'
/// (UpdatableFactor), or the rows c_r of constraints taken as columns C' (SparseCholesky's C A^-1 C').

#include <cstddef>
#include <vector>

#include "solver/lac/csc_pattern.hpp"

namespace saasgaps {

/// Each column has any number of entries (row, value), rows in the original (unpermuted) numbering;
/// stored like CSC: column c holds entries start[c] .. start[c + 1] - 1.
struct SparseColumns {
  std::vector<Index> start{0};
  std::vector<Index> row;
  std::vector<double> value;

  void clear() {
    start.assign(1, 0);
    row.clear();
    value.clear();
  }
  /// Adds an entry to the column being built; end_column() closes it.
  void add(Index r, double v) {
    row.push_back(r);
    value.push_back(v);
  }
  void end_column() { start.push_back(static_cast<Index>(row.size())); }
  [[nodiscard]] std::size_t size() const { return start.size() - 1; }
  [[nodiscard]] bool empty() const { return size() == 0; }
};

}  // namespace saasgaps
