#pragma once
/// A Cholesky factorization that takes rank-k updates and downdates, L D L' +- W W', for the exact
/// contact mode's small active-set changes (CHOLMOD's Modify module, cholmod_updown). It starts as a
/// copy of a SparseCholesky factorization converted to simplicial LDL' (the form updown works on);
/// SparseCholesky's own supernodal factor is left as it is.

#include <memory>
#include <span>
#include <vector>

#include "csc_pattern.hpp"
#include "sparse_cholesky.hpp"

namespace saasgaps {

/// The columns w of W, each with any number of entries (row, value), rows in the original
/// (unpermuted) numbering; stored like CSC: column c holds entries start[c] .. start[c + 1] - 1.
struct UpdateColumns {
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

class UpdatableFactor {
 public:
  UpdatableFactor();
  ~UpdatableFactor();
  UpdatableFactor(const UpdatableFactor&) = delete;
  UpdatableFactor& operator=(const UpdatableFactor&) = delete;

  /// Copies the last factorization of `factored` (which must have one) as simplicial LDL'.
  void copy(const SparseCholesky& factored);
  /// Copies another UpdatableFactor's factor as it stands (which must have one): a copy of the
  /// simplicial arrays, far cheaper than the conversion copy(SparseCholesky) makes.
  void copy(const UpdatableFactor& other);

  /// L D L' + W W' (add) or L D L' - W W' (downdate). Throws NotPositiveDefinite when a downdate
  /// loses definiteness (then the factor must be copied afresh).
  void update(const UpdateColumns& columns, bool add);

  /// x = (L D L')^-1 b.
  void solve(std::span<const double> b, std::span<double> x);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saasgaps
