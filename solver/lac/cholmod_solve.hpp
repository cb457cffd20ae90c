#pragma once
/// x = A^-1 b with a CHOLMOD factor of A, through cholmod_l_solve2 and workspaces kept between
/// calls (shared by SparseCholesky and UpdatableFactor), and a CHOLMOD view of our CSC arrays.

#include <cholmod.h>

#include <cstddef>
#include <span>

namespace saasgaps {

struct CholmodSolveWorkspace {
  cholmod_dense* X = nullptr;  // the solution
  cholmod_dense* Y = nullptr;
  cholmod_dense* E = nullptr;
  /// Frees the workspaces (call before cholmod_l_finish).
  void release(cholmod_common& common);
};

/// Solves with factor L into x; throws std::runtime_error when CHOLMOD fails.
/// system: CHOLMOD_A (x = A^-1 b), or a part of it (CHOLMOD_L, CHOLMOD_Lt: the triangular solves
/// alone, in the factor's permuted order).
void cholmod_solve_into(cholmod_factor* L, std::span<const double> b, std::span<double> x,
                        CholmodSolveWorkspace& work, cholmod_common& common, int system = CHOLMOD_A);

/// A cholmod_sparse that views (does not copy) sorted, packed CSC arrays with 64-bit indices:
/// colptr[ncol + 1], rowind[nnz] and, unless xtype is CHOLMOD_PATTERN, values[nnz]. stype 1: the
/// upper triangle of a symmetric matrix; 0: unsymmetric.
inline cholmod_sparse cholmod_csc_view(std::size_t nrow, std::size_t ncol, std::size_t nnz, void* colptr, void* rowind,
                                       void* values, int stype, int xtype) {
  cholmod_sparse A{};
  A.nrow = nrow;
  A.ncol = ncol;
  A.nzmax = nnz;
  A.p = colptr;
  A.i = rowind;
  A.x = values;
  A.stype = stype;
  A.itype = CHOLMOD_LONG;
  A.xtype = xtype;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

}  // namespace saasgaps
