#include "solver/lac/updatable_factor.hpp"

#include <cholmod.h>

#include "solver/base/thread_environment.hpp"
#include "solver/lac/cholmod_memory.hpp"
#include "solver/lac/cholmod_solve.hpp"

#include <algorithm>
#include <cstring>
#include <cassert>
#include <stdexcept>
#include <string>

namespace saasgaps {

struct UpdatableFactor::Impl {
  cholmod_common common{};
  // Simplicial LDL': its pattern arrays (p, i, nz, next, prev, Perm, ColCount) are its own; its
  // values x are the lent supernodal factor's memory after convert(), never freed here, and its own
  // after copy().
  cholmod_factor* L = nullptr;
  bool owns_values = false;
  std::uint64_t analysis = 0;  // SparseCholesky::analysis_id the pattern was derived from
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
    release();
    work.release(common);
    cholmod_l_finish(&common);
  }
  void fail(const char* what) const {
    throw std::runtime_error(std::string("CHOLMOD ") + what + " failed (status " + std::to_string(common.status) + ")");
  }
  void release() {
    if (L == nullptr) return;
    if (!owns_values) L->x = nullptr;  // lent, not ours
    cholmod_l_free_factor(&L, &common);
    owns_values = false;
    analysis = 0;
  }

  /// The packed simplicial pattern of supernodal S: column j of supernode s holds the rows of s from
  /// j down (its diagonal block's lower triangle and the rows below the block), as
  /// cholmod_change_factor lays it out; the columns in natural order.
  void derive_pattern(const cholmod_factor& S, std::uint64_t id) {
    release();
    const auto n = static_cast<Index>(S.n);
    const auto* super = static_cast<const Index*>(S.super);
    const auto* pi = static_cast<const Index*>(S.pi);
    const auto* ls = static_cast<const Index*>(S.s);
    Index entries = 0;
    for (std::size_t s = 0; s < S.nsuper; ++s) {
      const Index columns = super[s + 1] - super[s], rows = pi[s + 1] - pi[s];
      entries += columns * (columns + 1) / 2 + columns * (rows - columns);
    }
    L = cholmod_l_allocate_factor(S.n, &common);
    if (L == nullptr) fail("allocate_factor");
    const auto allocate = [this](std::size_t count) {
      void* block = cholmod_l_malloc(count, sizeof(Index), &common);
      if (block == nullptr) fail("malloc");
      return static_cast<Index*>(block);
    };
    auto* p = allocate(S.n + 1);
    L->p = p;
    auto* nz = allocate(S.n);
    L->nz = nz;
    auto* next = allocate(S.n + 2);
    L->next = next;
    auto* prev = allocate(S.n + 2);
    L->prev = prev;
    auto* li = allocate(static_cast<std::size_t>(entries));
    L->i = li;
    prefault_cholmod_block(li);  // its pages faulted in at once rather than trapped one by one
    L->nzmax = static_cast<std::size_t>(entries);
    L->ordering = S.ordering;
    std::copy_n(static_cast<const Index*>(S.Perm), n, static_cast<Index*>(L->Perm));
    std::copy_n(static_cast<const Index*>(S.ColCount), n, static_cast<Index*>(L->ColCount));
    Index k = 0;
    for (std::size_t s = 0; s < S.nsuper; ++s) {
      const Index rows = pi[s + 1] - pi[s];
      for (Index j = super[s]; j < super[s + 1]; ++j) {
        p[j] = k;
        for (Index row = j - super[s]; row < rows; ++row) li[k++] = ls[pi[s] + row];
        nz[j] = k - p[j];
      }
    }
    p[n] = k;
    assert(k == entries);
    // The doubly linked list of columns in natural order (head n + 1, tail n), as CHOLMOD builds it.
    next[n + 1] = 0;
    prev[n + 1] = -1;
    next[n] = -1;
    prev[n] = n - 1;
    for (Index j = 0; j < n; ++j) {
      next[j] = j + 1;
      prev[j] = j - 1;
    }
    prev[0] = n + 1;
    L->is_monotonic = true;
    L->is_ll = false;
    L->is_super = false;
    analysis = id;
    inverse.resize(static_cast<std::size_t>(n));
    for (Index j = 0; j < n; ++j) inverse[static_cast<const Index*>(L->Perm)[j]] = j;
  }
};

UpdatableFactor::UpdatableFactor() : impl_(std::make_unique<Impl>()) {}
UpdatableFactor::~UpdatableFactor() = default;

void UpdatableFactor::convert(SparseCholesky& factored) {
  Impl& m = *impl_;
  const std::uint64_t id = factored.analysis_id();
  cholmod_factor& S = *factored.factor_for_conversion();
  assert(S.is_super && S.is_ll && S.xtype == CHOLMOD_REAL && S.minor == S.n && "a successful supernodal LL'");
  // A factor whose values are its own (a copy) is rebuilt around the lent ones.
  if (m.L == nullptr || m.analysis != id || m.owns_values) m.derive_pattern(S, id);
  m.L->x = S.x;
  m.L->xtype = CHOLMOD_REAL;
  m.L->dtype = CHOLMOD_DOUBLE;
  m.L->minor = S.n;
  // Column by column in order, into the same array: column j's packed start is at most where its
  // diagonal sits in the supernode (the packed form skips the diagonal blocks' upper triangles), so
  // every entry moves down or stays, after it was read. The arithmetic of cholmod_change_factor's
  // LL' -> LDL' conversion.
  auto* x = static_cast<double*>(S.x);
  const auto* super = static_cast<const Index*>(S.super);
  const auto* pi = static_cast<const Index*>(S.pi);
  const auto* px = static_cast<const Index*>(S.px);
  Index k = 0;
  for (std::size_t s = 0; s < S.nsuper; ++s) {
    const Index rows = pi[s + 1] - pi[s];
    for (Index jj = 0; jj < super[s + 1] - super[s]; ++jj) {
      const Index diagonal = px[s] + jj + jj * rows;
      const double ljj = x[diagonal];
      assert(ljj > 0.0 && k <= diagonal);
      x[k++] = ljj * ljj;
      for (Index q = diagonal + 1; q < px[s] + (jj + 1) * rows; ++q) x[k++] = x[q] / ljj;
    }
  }
  assert(k == static_cast<Index>(m.L->nzmax));
}

void UpdatableFactor::copy(const UpdatableFactor& other) {
  assert(other.impl_->L != nullptr && "copy of an UpdatableFactor without a factor");
  Impl& m = *impl_;
  const cholmod_factor& from = *other.impl_->L;
  cholmod_factor* to = m.L;
  // Into the arrays already there when they have the sizes (the usual case: a copy per solve of a
  // factor whose updates added no entries); allocating afresh costs page faults on every page, about
  // as much again as the copy.
  if (to != nullptr && m.owns_values && !to->is_super && !from.is_super && to->n == from.n &&
      to->nzmax == from.nzmax && to->xtype == from.xtype && to->is_ll == from.is_ll) {
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
    m.release();
    m.L = cholmod_l_copy_factor(other.impl_->L, &m.common);
    if (m.L == nullptr) m.fail("copy_factor");
    m.owns_values = true;
  }
  m.analysis = other.impl_->analysis;
  m.inverse = other.impl_->inverse;
}

void UpdatableFactor::update(const SparseColumns& columns, bool add) {
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
  [[maybe_unused]] const void* const values_before = m.L->x;
  if (!cholmod_l_updown(add, &W, m.L, &m.common)) m.fail("updown");
  assert(m.L->x == values_before && "L's pattern holds the update: no column was reallocated");
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
