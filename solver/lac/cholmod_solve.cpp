#include "solver/lac/cholmod_solve.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

namespace saasgaps {

void CholmodSolveWorkspace::release(cholmod_common& common) {
  cholmod_l_free_dense(&X, &common);
  cholmod_l_free_dense(&Y, &common);
  cholmod_l_free_dense(&E, &common);
}

void cholmod_solve_into(cholmod_factor* L, std::span<const double> b, std::span<double> x,
                        CholmodSolveWorkspace& work, cholmod_common& common, int system) {
  const std::size_t n = L->n;
  assert(b.size() == n && x.size() == n);
  cholmod_dense B{};
  B.nrow = n;
  B.ncol = 1;
  B.nzmax = n;
  B.d = n;
  B.x = const_cast<double*>(b.data());
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_l_solve2(system, L, &B, nullptr, &work.X, nullptr, &work.Y, &work.E, &common)) {
    throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(common.status) + ")");
  }
  const auto* result = static_cast<const double*>(work.X->x);
  std::copy(result, result + n, x.begin());
}

}  // namespace saasgaps
