#pragma once
/// x = A^-1 b with a CHOLMOD factor of A, through cholmod_l_solve2 and workspaces kept between
/// calls (shared by SparseCholesky and UpdatableFactor).

#include <cholmod.h>

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
void cholmod_solve_into(cholmod_factor* L, std::span<const double> b, std::span<double> x,
                        CholmodSolveWorkspace& work, cholmod_common& common);

}  // namespace saasgaps
