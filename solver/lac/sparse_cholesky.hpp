#pragma once
/// Sparse symmetric positive-definite solver on CHOLMOD's supernodal Cholesky factorization.
/// The symbolic analysis (METIS fill-reducing ordering, elimination tree, supernodes) is done once
/// per pattern; factorize() only repeats the numeric part in the same factor object, which after
/// the first call allocates nothing. solve() reuses its workspace too.

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/ordering_cache.hpp"
#include "solver/lac/sparse_columns.hpp"

struct cholmod_factor_struct;

namespace saasgaps {

/// The matrix is not positive definite, or so close to singular that the answer would be noise.
/// columns are the original (unpermuted) indices where the factorization broke down.
class NotPositiveDefinite : public std::runtime_error {
 public:
  NotPositiveDefinite(const std::string& what, std::vector<Index> columns)
      : std::runtime_error(what), columns_(std::move(columns)) {}
  [[nodiscard]] const std::vector<Index>& columns() const { return columns_; }

 private:
  std::vector<Index> columns_;
};

/// The fill-reducing ordering of the symbolic analysis.
/// nested_dissection: METIS (on the node groups when given): the least fill and flops on 2-D
/// meshes, but computing it costs about a numeric factorization of the mechanical matrix.
/// minimum_degree: AMD on the unknowns, groups ignored: about a tenth of METIS's time for more fill;
/// the better trade where a factorization costs little beside its analysis (a scalar field's
/// matrix, factorized once or a few times: thermal_analysis.cpp).
enum class FillOrdering { nested_dissection, minimum_degree };

class SparseCholesky {
 public:
  /// A pivot d_j = L_jj^2 smaller than this fraction of A_jj means all stiffness at j came from
  /// cancellation: a mechanism in exact arithmetic (an unrestrained body or unconnected node).
  static constexpr double singular_pivot_ratio = 1.0e-12;

  /// Symbolic analysis of an upper-triangular pattern. The pattern must outlive this object.
  /// groups (optional, one entry per unknown): unknowns with the same group share their sparsity
  /// (the two displacement components of a node). The fill-reducing ordering is then computed on
  /// the graph of groups, about four times smaller, and expanded; without groups, on the unknowns.
  /// cache (optional, with groups): the symbolic analysis of a pattern seen before is loaded from
  /// its directory instead of computed (the whole supernodal factor, else the node-graph ordering),
  /// and a computed one is saved there.
  /// fill: minimum_degree uses neither groups nor cache.
  explicit SparseCholesky(const CscPattern& pattern, std::span<const Index> groups = {},
                          const OrderingCache* cache = nullptr,
                          FillOrdering fill = FillOrdering::nested_dissection);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Numeric factorization of the matrix with the analysed pattern and these values.
  /// Throws NotPositiveDefinite naming the failing columns.
  void factorize(std::span<const double> values);

  /// x = A^-1 b with the last factorization. Not while the factor is lent (factor_for_conversion).
  void solve(std::span<const double> b, std::span<double> x);

  /// Z = L^-1 P C' for a few sparse columns C' (rows in the original numbering) with the last
  /// factorization, over the columns' reach in the elimination tree alone (the supernodes on the
  /// paths from their rows to the root; every other row of Z is zero): supernodal forward solves in
  /// dense blocks (OpenBLAS). Each supernode keeps only its band, the columns from the first to the
  /// last whose paths pass it (rows in chain order along a surface: nearby rows meet low in the tree),
  /// so for m columns whose reach holds a share f of L the work is at most about 2 m f nnz(L) flops,
  /// and a window of adjacent contact rows (f a few per cent, bands about a fifth of m) costs a small
  /// fraction of m solves.
  /// Not while the factor is lent (factor_for_conversion).
  struct Reach {
    std::vector<Index> positions;  ///< the permuted position (row of L) of each row of Z
    Index columns = 0;             ///< m
    /// The supernodes of the reach, in order: rows [first_row, first_row + rows) of Z, nonzero only
    /// in columns [first_column, first_column + columns), stored from z[offset] row after row.
    struct Block {
      Index first_row = 0, rows = 0, first_column = 0, columns = 0;
      std::size_t offset = 0;
    };
    std::vector<Block> blocks;
    std::vector<double> z;  ///< the blocks' bands (a fifth of positions.size() x m for a contact surface)
    /// Z'Z as a dense m x m matrix, column-major.
    [[nodiscard]] std::vector<double> gram() const;
  };
  [[nodiscard]] Reach forward_columns(const SparseColumns& columns);
  /// C A^-1 C' = forward_columns(columns).gram(): a dense m x m matrix, column-major.
  [[nodiscard]] std::vector<double> inverse_form(const SparseColumns& columns);
  /// The two halves of solve(): y = L^-1 P b, in the factor's (permuted) order; x = P' L^-T y.
  /// Between them a caller may change y (SetCorrection adds Z y_D on a reach).
  void forward(std::span<const double> b, std::span<double> y);
  void backward(std::span<const double> y, std::span<double> x);
  [[nodiscard]] Index size() const;
  [[nodiscard]] double factor_nonzeros() const;  ///< nnz(L)
  [[nodiscard]] double factor_flops() const;     ///< floating-point operations of one factorization
  [[nodiscard]] const char* ordering() const;    ///< the fill-reducing ordering in use
  [[nodiscard]] bool ordering_from_cache() const;  ///< loaded from the OrderingCache, not computed
  /// The whole symbolic analysis loaded from the cache's directory (SymbolicCache): no METIS and
  /// no cholmod_analyze. Implies ordering_from_cache().
  [[nodiscard]] bool analysis_from_cache() const;
  [[nodiscard]] double ordering_seconds() const;  ///< computing (or loading) the ordering, or the whole analysis

  /// The last factorization, read-only.
  [[nodiscard]] const cholmod_factor_struct* factor() const;
  /// The last factorization (supernodal LL'), lent to UpdatableFactor::convert, which overwrites its
  /// values with the simplicial LDL' form in the same memory instead of copying them. Until the next
  /// factorize() the values are no longer this factorization's: solve() must not be called. The
  /// symbolic analysis is untouched, so the next factorize() is supernodal again.
  [[nodiscard]] cholmod_factor_struct* factor_for_conversion();
  /// A number no other analysis in this process has: what UpdatableFactor keys the simplicial
  /// pattern it derives from this analysis by.
  [[nodiscard]] std::uint64_t analysis_id() const;

  /// Most BLAS threads a factorization may use (default: the cores). Factorizations under about
  /// 10 Gflop run on one: below that the threads cost more than they give (measured on 2 cores).
  /// A server solving several jobs at once sets 1.
  static void set_max_blas_threads(int threads);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saasgaps
