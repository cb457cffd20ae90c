#include "updatable_factor.hpp"

#include <cholmod.h>

#include "cholmod_solve.hpp"
#include "thread_environment.hpp"

#include <algorithm>
#include <cstring>
#include <cassert>
#include <stdexcept>
#include <string>

namespace saasgaps {

struct UpdatableFactor::Impl {
  cholmod_common common{};
  cholmod_factor* L = nullptr;
  CholmodSolveWorkspace work;
  std::vector<Index> inverse;  // permuted position of each original row
  std::vector<Index> colptr, rowind;
  std::vector<double> values;
  std::vector<std::pair<Index, double>> column;
  std::vector<double> pivots;  // d_j before a downdate

  Impl() {
    configure_solver_threads();  // CHOLMOD's OpenMP loops serial on this thread, as for SparseCholesky
    cholmod_l_start(&common);
    common.print = 0;
  }
  ~Impl() {
    cholmod_l_free_factor(&L, &common);
    work.release(common);
    cholmod_l_finish(&common);
  }
  void fail(const char* what) const {
    throw std::runtime_error(std::string("CHOLMOD ") + what + " failed (status " + std::to_string(common.status) + ")");
  }
};

UpdatableFactor::UpdatableFactor() : impl_(std::make_unique<Impl>()) {}
UpdatableFactor::~UpdatableFactor() = default;

void UpdatableFactor::copy(const SparseCholesky& factored) {
  Impl& m = *impl_;
  cholmod_l_free_factor(&m.L, &m.common);
  m.L = cholmod_l_copy_factor(const_cast<cholmod_factor*>(factored.factor()), &m.common);
  if (m.L == nullptr) m.fail("copy_factor");
  // Simplicial LDL', packed and monotonic: the form cholmod_updown works on.
  if (!cholmod_l_change_factor(CHOLMOD_REAL, false, false, true, true, m.L, &m.common)) m.fail("change_factor");
  const auto n = static_cast<Index>(m.L->n);
  const auto* perm = static_cast<const Index*>(m.L->Perm);
  m.inverse.resize(static_cast<std::size_t>(n));
  for (Index k = 0; k < n; ++k) m.inverse[perm[k]] = k;
}

void UpdatableFactor::copy(const UpdatableFactor& other) {
  assert(other.impl_->L != nullptr && "copy of an UpdatableFactor without a factor");
  Impl& m = *impl_;
  const cholmod_factor& from = *other.impl_->L;
  cholmod_factor* to = m.L;
  // Into the arrays already there when they have the sizes (the usual case: a copy per solve of a
  // factor whose updates added no entries); allocating afresh costs page faults on every page, about
  // as much again as the copy.
  if (to != nullptr && !to->is_super && !from.is_super && to->n == from.n && to->nzmax == from.nzmax &&
      to->xtype == from.xtype && to->is_ll == from.is_ll) {
    const std::size_t n = from.n;
    std::memcpy(to->Perm, from.Perm, n * sizeof(Index));
    std::memcpy(to->ColCount, from.ColCount, n * sizeof(Index));
    std::memcpy(to->p, from.p, (n + 1) * sizeof(Index));
    std::memcpy(to->i, from.i, from.nzmax * sizeof(Index));
    std::memcpy(to->x, from.x, from.nzmax * sizeof(double));
    std::memcpy(to->nz, from.nz, n * sizeof(Index));
    std::memcpy(to->next, from.next, (n + 2) * sizeof(Index));
    std::memcpy(to->prev, from.prev, (n + 2) * sizeof(Index));
    if (to->IPerm != nullptr) {  // the inverse permutation a solve may have made: of the new Perm
      auto* inverse = static_cast<Index*>(to->IPerm);
      const auto* perm = static_cast<const Index*>(to->Perm);
      for (std::size_t k = 0; k < n; ++k) inverse[perm[k]] = static_cast<Index>(k);
    }
    to->minor = from.minor;
    to->ordering = from.ordering;
    to->is_monotonic = from.is_monotonic;
  } else {
    cholmod_l_free_factor(&m.L, &m.common);
    m.L = cholmod_l_copy_factor(other.impl_->L, &m.common);
    if (m.L == nullptr) m.fail("copy_factor");
  }
  m.inverse = other.impl_->inverse;
}

void UpdatableFactor::update(const UpdateColumns& columns, bool add) {
  if (columns.empty()) return;
  Impl& m = *impl_;
  // W with its rows permuted like L (updown wants P W), sorted within each column.
  m.colptr.assign(1, 0);
  m.rowind.clear();
  m.values.clear();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    m.column.clear();
    for (Index k = columns.start[c]; k < columns.start[c + 1]; ++k) {
      m.column.emplace_back(m.inverse[columns.row[k]], columns.value[k]);
    }
    std::sort(m.column.begin(), m.column.end());
    for (const auto& [row, value] : m.column) {
      m.rowind.push_back(row);
      m.values.push_back(value);
    }
    m.colptr.push_back(static_cast<Index>(m.rowind.size()));
  }
  cholmod_sparse W = cholmod_csc_view(m.L->n, columns.size(), m.rowind.size(), m.colptr.data(), m.rowind.data(),
                                      m.values.data(), 0, CHOLMOD_REAL);
  // Simplicial LDL': d_j is the first entry of column j. A downdate that removes the only stiffness
  // of a mode (the last constraint holding a body) leaves its pivot at round-off, not negative:
  // SparseCholesky's rule (a pivot below singular_pivot_ratio of what it was) catches it.
  const auto* p = static_cast<const Index*>(m.L->p);
  const auto pivot = [&m, p](std::size_t j) { return static_cast<const double*>(m.L->x)[p[j]]; };
  if (!add) {
    m.pivots.resize(m.L->n);
    for (std::size_t j = 0; j < m.L->n; ++j) m.pivots[j] = pivot(j);
  }
  if (!cholmod_l_updown(add, &W, m.L, &m.common)) m.fail("updown");
  if (m.common.status == CHOLMOD_NOT_POSDEF) {
    throw NotPositiveDefinite("a downdate lost positive definiteness", {});
  }
  for (std::size_t j = 0; !add && j < m.L->n; ++j) {
    if (pivot(j) < SparseCholesky::singular_pivot_ratio * m.pivots[j]) {
      throw NotPositiveDefinite("a downdate left a pivot at round-off", {static_cast<const Index*>(m.L->Perm)[j]});
    }
  }
}

void UpdatableFactor::solve(std::span<const double> b, std::span<double> x) {
  cholmod_solve_into(impl_->L, b, x, impl_->work, impl_->common);
}

}  // namespace saasgaps
