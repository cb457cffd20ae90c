#pragma once
/// A Cholesky factorization that takes rank-k updates and downdates, L D L' +- W W', for the exact
/// contact mode's small active-set changes (CHOLMOD's Modify module, cholmod_updown). It starts as a
/// copy of a SparseCholesky factorization converted to simplicial LDL' (the form updown works on);
/// SparseCholesky's own supernodal factor is left as it is.

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "csc_pattern.hpp"
#include "sparse_cholesky.hpp"

namespace saasgaps {

/// One column w of W: entries (row, value), rows in the original (unpermuted) numbering.
struct UpdateColumn {
  std::array<Index, 6> row{};
  std::array<double, 6> value{};
  int count = 0;
};

class UpdatableFactor {
 public:
  UpdatableFactor();
  ~UpdatableFactor();
  UpdatableFactor(const UpdatableFactor&) = delete;
  UpdatableFactor& operator=(const UpdatableFactor&) = delete;

  /// Copies the last factorization of `factored` (which must have one) as simplicial LDL'.
  void copy(const SparseCholesky& factored);

  /// L D L' + W W' (add) or L D L' - W W' (downdate). Throws NotPositiveDefinite when a downdate
  /// loses definiteness (then the factor must be copied afresh).
  void update(std::span<const UpdateColumn> columns, bool add);

  /// x = (L D L')^-1 b.
  void solve(std::span<const double> b, std::span<double> x);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saasgaps
