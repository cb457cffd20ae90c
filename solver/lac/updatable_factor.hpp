#pragma once
/// A Cholesky factorization that takes rank-k updates and downdates, L D L' +- W W', for the exact
/// contact mode's small active-set changes (CHOLMOD's Modify module, cholmod_updown). It starts from
/// a SparseCholesky factorization converted to simplicial LDL' (the form updown works on) in that
/// factorization's own memory: no copy of the values (the copy cost about 0.8 of a factorization,
/// most of it the first touch of freshly mapped pages), and the simplicial pattern, which depends on
/// the symbolic analysis alone, is derived once per analysis and kept.

#include <memory>
#include <span>
#include <vector>

#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/lac/sparse_columns.hpp"

namespace saasgaps {

class UpdatableFactor {
 public:
  UpdatableFactor();
  ~UpdatableFactor();
  UpdatableFactor(const UpdatableFactor&) = delete;
  UpdatableFactor& operator=(const UpdatableFactor&) = delete;

  /// Takes the last factorization of `factored` (which must have one) as simplicial LDL', converted
  /// in place: d_j = L_jj^2, l_ij = L_ij / L_jj, as cholmod_change_factor would (the same digits).
  /// `factored` cannot solve until it factorizes again (SparseCholesky::factor_for_conversion), and
  /// this factor is valid only until then: its values are that memory.
  void convert(SparseCholesky& factored);
  /// Copies another UpdatableFactor's factor as it stands (which must have one) into memory of its
  /// own: into the arrays it already owns when they have the sizes (a memcpy), otherwise into fresh
  /// ones. Never into a converted factorization's memory, which `other` may be.
  void copy(const UpdatableFactor& other);

  /// L D L' + W W' (add) or L D L' - W W' (downdate). Throws NotPositiveDefinite when a downdate
  /// loses definiteness (then the matrix must be factorized afresh). Every column of W must have its
  /// rows coupled pairwise in the analysed pattern (the rows of a constraint: ConstraintRows), so
  /// that L's pattern holds the updated factor's and nothing is reallocated.
  void update(const SparseColumns& columns, bool add);

  /// x = (L D L')^-1 b.
  void solve(std::span<const double> b, std::span<double> x);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saasgaps
