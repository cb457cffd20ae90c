#include "solver/contact/constraint_rows.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "solver/base/errors.hpp"

namespace saasgaps {

double contact_start(std::span<const double> g0) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const double g : g0) smallest = std::min(smallest, g);
  // An interference of -smallest is resolved by the parts deforming about that much, which closes
  // open gaps up to about that size too: starting from the rows with g0 <= 0 alone, the contact
  // then spreads over several sets each far from the last (an eccentric fit: 2 factorizations).
  if (smallest < 0.0) return -smallest;
  return smallest + 0.01 * smallest;
}

ConstraintRows::ConstraintRows(const DofMap& dofs, const CscPattern& pattern) : dofs_(dofs), pattern_(pattern) {
  diagonal_.resize(static_cast<std::size_t>(pattern.n));
  for (Index j = 0; j < pattern.n; ++j) diagonal_[j] = pattern.find(j, j);
  b_.resize(static_cast<std::size_t>(pattern.n));
}

std::size_t ConstraintRows::add(std::span<const int> nodes, std::span<const double> weights, const Vec2& direction,
                                double g0) {
  assert(nodes.size() == weights.size());
  std::vector<Vec2> coefficients(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) coefficients[k] = weights[k] * direction;
  return add(nodes, coefficients, g0);
}

std::size_t ConstraintRows::add(std::span<const int> nodes, std::span<const Vec2> coefficients, double g0) {
  assert(nodes.size() == coefficients.size());
  Row row;
  row.first = entries_.size();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    for (int dir = 0; dir < 2; ++dir) {
      // cos(90 degrees) is 6e-17, not 0: such a component is no coupling (and would give a row
      // whose only free unknown is across the direction a vanishing penalty).
      const double coefficient = coefficients[k][dir];
      if (std::abs(coefficient) <= 1.0e-12 * coefficients[k].norm()) continue;
      const Index eq = dofs_.equation(nodes[k], dir);
      if (eq >= 0) {
        entries_.push_back({eq, coefficient});
      } else {
        g0 += coefficient * dofs_.prescribed(nodes[k], dir);
      }
    }
  }
  row.last = entries_.size();
  row.prescribed_g0 = row.g0 = g0;
  row.first_product = positions_.size();
  const std::span<const Entry> e = std::span<const Entry>(entries_).subspan(row.first, row.last - row.first);
  for (std::size_t a = 0; a < e.size(); ++a) {
    for (std::size_t b = a; b < e.size(); ++b) {
      const Index position = pattern_.find(e[a].equation, e[b].equation);
      assert(position >= 0 && "the pattern must couple the unknowns of a constraint row");
      positions_.push_back(position);
      products_.push_back(e[a].coefficient * e[b].coefficient);
    }
  }
  row.last_product = positions_.size();
  rows_.push_back(row);
  return rows_.size() - 1;
}

double ConstraintRows::value(std::size_t r, std::span<const double> u) const {
  double g = rows_[r].g0;
  for (const Entry& e : entries(r)) g += e.coefficient * u[e.equation];
  return g;
}

void ConstraintRows::add_load(std::size_t r, double load, std::span<double> b) const {
  for (const Entry& e : entries(r)) b[e.equation] += e.coefficient * load;
}

void ConstraintRows::set_penalties(std::span<const double> values) {
  // c_r^T diag(K) c_r is the stiffness the row's nodes have.
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    Row& row = rows_[r];
    row.stiffness = 0.0;
    double flexibility = 0.0;  // c_r^T diag(K)^-1 c_r
    for (const Entry& e : entries(r)) {
      const double d = values[diagonal_[e.equation]];
      row.stiffness += e.coefficient * e.coefficient * d;
      flexibility += e.coefficient * e.coefficient / d;
    }
    row.rho = penalty_factor * std::min(row.stiffness, jacobi_multiple / flexibility);
  }
  factored_.clear();
  held_.clear();
  corrected_.clear();
  cholesky_ = nullptr;
}

void ConstraintRows::factor(SparseCholesky& cholesky, std::span<const double> values,
                            std::span<const std::uint8_t> active) {
  values_.assign(values.begin(), values.end());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (!active[r]) continue;
    const Row& row = rows_[r];
    for (std::size_t k = row.first_product; k < row.last_product; ++k) values_[positions_[k]] += row.rho * products_[k];
  }
  corrected_.clear();
  correction_ = SetCorrection();  // its forward solves were on the factorization replaced
  converted_ = false;
  window_rows_.clear();  // condense()'s too
  window_reach_.reset();
  cholesky.factorize(values_);
}

void ConstraintRows::update(std::span<const std::uint8_t> active) {
  for (const bool add : {true, false}) {
    columns_.clear();
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      if (held_[r] == active[r] || static_cast<bool>(active[r]) != add) continue;
      // rho_r c_r c_r^T = w w^T with w = sqrt(rho_r) c_r.
      add_column(r, std::sqrt(rows_[r].rho));
    }
    updatable_.update(columns_, add);
  }
}

void ConstraintRows::add_column(std::size_t r, double scale) {
  for (const Entry& e : entries(r)) columns_.add(e.equation, scale * e.coefficient);
  columns_.end_column();
}

bool ConstraintRows::correct(std::span<const std::uint8_t> active) {
  columns_.clear();
  std::vector<double> penalties;
  std::vector<std::size_t> changed;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (factored_[r] == active[r]) continue;
    add_column(r, 1.0);
    changed.push_back(r);
    penalties.push_back(active[r] ? rows_[r].rho : -rows_[r].rho);
  }
  // Rows the look-ahead condensed on this factorization (window_rows_, sorted): their columns of
  // its forward solves instead of solving again.
  std::vector<std::size_t> subset;
  for (const std::size_t r : changed) {
    const auto at = std::lower_bound(window_rows_.begin(), window_rows_.end(), r);
    if (at == window_rows_.end() || *at != r) break;
    subset.push_back(static_cast<std::size_t>(at - window_rows_.begin()));
  }
  if (!window_rows_.empty() && subset.size() == changed.size()) {
    correction_.set(*cholesky_, window_reach_, window_gram_, subset, penalties);
  } else {
    correction_.set(*cholesky_, columns_, penalties);
  }
  if (correction_.loss() > max_correction_loss) return false;
  corrected_.assign(active.begin(), active.end());
  return true;
}

void ConstraintRows::solve_held(std::span<const double> b, std::span<double> x) {
  if (!corrected_.empty()) {
    correction_.solve(b, x);
  } else if (held_.empty()) {
    cholesky_->solve(b, x);
  } else {
    updatable_.solve(b, x);
  }
}

bool ConstraintRows::hold(SparseCholesky& cholesky, std::span<const double> values,
                          std::span<const std::uint8_t> active) {
  assert(active.size() == rows_.size());
  // While the supernodal factorization of K_F is intact, a set near F is solved on it through a
  // correction (set_correction.hpp): supernodal solves, no conversion, no update.
  if (cholesky_ == &cholesky && !factored_.empty() && !converted_) {
    std::size_t from_factored = 0;
    for (std::size_t r = 0; r < rows_.size(); ++r) from_factored += factored_[r] != active[r];
    if (from_factored == 0) {
      corrected_.clear();
      return false;
    }
    if (from_factored <= max_correction_rank && correct(active)) return false;
  }
  corrected_.clear();
  // The step's rank: rows that change from the set the factor (or its updated copy) holds.
  const std::vector<std::uint8_t>& from = held_.empty() ? factored_ : held_;
  int distance = 0;
  for (std::size_t r = 0; r < rows_.size() && !from.empty(); ++r) distance += from[r] != active[r];
  if (!from.empty() && cholesky_ == &cholesky && distance <= max_update_rank) {
    try {
      if (held_.empty()) {
        updatable_.convert(cholesky);
        converted_ = true;
        held_ = factored_;
      }
      update(active);
      held_.assign(active.begin(), active.end());
      return false;
    } catch (const NotPositiveDefinite&) {
      held_.clear();  // a downdate lost definiteness to round-off: factorize afresh
    }
  }
  factored_.clear();  // a factorization that throws holds nothing
  held_.clear();
  factor(cholesky, values, active);
  cholesky_ = &cholesky;
  factored_.assign(active.begin(), active.end());
  return true;
}

bool ConstraintRows::hold_from(SparseCholesky& cholesky, std::span<const double> values,
                               std::span<const std::uint8_t> base, std::span<const std::uint8_t> active) {
  assert(base.size() == rows_.size() && active.size() == rows_.size());
  int distance = 0;
  for (std::size_t r = 0; r < rows_.size(); ++r) distance += base[r] != active[r];
  if (distance > max_update_rank) return hold(cholesky, values, active);
  bool factorized = false;
  const bool kept = !base_.empty() && std::equal(base.begin(), base.end(), base_.begin(), base_.end()) &&
                    std::equal(values.begin(), values.end(), base_values_.begin(), base_values_.end());
  if (!kept) {
    base_.clear();  // a factorization that throws keeps nothing
    factored_.clear();
    held_.clear();
    factor(cholesky, values, base);
    cholesky_ = &cholesky;
    factorized = true;
    // Converted in place, the supernodal factor is used up; the kept K_base is a copy in memory of
    // its own, which later factorizations of `cholesky` cannot overwrite.
    updatable_.convert(cholesky);
    converted_ = true;
    base_factor_.copy(updatable_);
    base_.assign(base.begin(), base.end());
    base_values_.assign(values.begin(), values.end());
  } else {
    updatable_.copy(base_factor_);
  }
  corrected_.clear();
  try {
    held_.assign(base.begin(), base.end());
    update(active);
    held_.assign(active.begin(), active.end());
    cholesky_ = &cholesky;
    return factorized;
  } catch (const NotPositiveDefinite&) {
    held_.clear();  // a downdate lost definiteness to round-off: factorize K_active afresh
  }
  factor(cholesky, values, active);
  cholesky_ = &cholesky;
  factored_.assign(active.begin(), active.end());
  return true;
}

std::span<const std::size_t> ConstraintRows::neighbours(std::size_t r) {
  if (neighbour_start_.size() != rows_.size() + 1) {
    // (unknown, row) for every entry, sorted: the rows of each constrained unknown. Then for every
    // pattern entry (i, j) between two constrained unknowns (column j of the upper triangle holds
    // its i <= j), rows(i) x rows(j) are neighbours. The rows of column j's entries are gathered
    // once each first (`near`, marked by j): the rows of a quad8 face share most of their unknowns,
    // and the pairs taken entry by entry were 8 times as many (1.4 million links where 175,208 remain,
    // 0.78 s where this takes 0.02-0.05 s, on the quad8 ring fit at 1.5 x 10^5 unknowns).
    std::vector<std::pair<Index, std::size_t>> by_unknown;
    for (std::size_t row = 0; row < rows_.size(); ++row) {
      for (const Entry& e : entries(row)) by_unknown.emplace_back(e.equation, row);
    }
    std::sort(by_unknown.begin(), by_unknown.end());
    const auto rows_of = [&](Index unknown) {
      const auto first = std::lower_bound(by_unknown.begin(), by_unknown.end(), std::pair<Index, std::size_t>(unknown, 0));
      auto last = first;
      while (last != by_unknown.end() && last->first == unknown) ++last;
      return std::span<const std::pair<Index, std::size_t>>(first, last);
    };
    std::vector<std::pair<std::size_t, std::size_t>> links;
    std::vector<Index> marked(rows_.size(), -1);
    std::vector<std::size_t> near;
    for (auto k = by_unknown.begin(); k != by_unknown.end();) {
      const Index j = k->first;
      const auto at_j = rows_of(j);
      k += static_cast<std::ptrdiff_t>(at_j.size());
      near.clear();
      for (Index p = pattern_.colptr[j]; p < pattern_.colptr[j + 1]; ++p) {
        for (const auto& a : rows_of(pattern_.rowind[p])) {
          if (marked[a.second] == j) continue;
          marked[a.second] = j;
          near.push_back(a.second);
        }
      }
      for (const std::size_t a : near) {
        for (const auto& b : at_j) {
          if (a == b.second) continue;
          links.emplace_back(a, b.second);
          links.emplace_back(b.second, a);
        }
      }
    }
    std::sort(links.begin(), links.end());
    links.erase(std::unique(links.begin(), links.end()), links.end());
    neighbour_start_.assign(rows_.size() + 1, 0);
    neighbours_.clear();
    for (const auto& [a, b] : links) {
      ++neighbour_start_[a + 1];
      neighbours_.push_back(b);
    }
    for (std::size_t row = 0; row < rows_.size(); ++row) neighbour_start_[row + 1] += neighbour_start_[row];
  }
  return std::span<const std::size_t>(neighbours_).subspan(neighbour_start_[r], neighbour_start_[r + 1] - neighbour_start_[r]);
}

bool ConstraintRows::factorized(std::span<const std::uint8_t> active) const {
  return cholesky_ != nullptr && held_.empty() && corrected_.empty() && !converted_ &&
         std::equal(active.begin(), active.end(), factored_.begin(), factored_.end());
}

bool ConstraintRows::condense(std::span<const std::size_t> window, std::span<const std::uint8_t> active,
                              std::span<const double> force, std::span<const double> u, Eigen::MatrixXd& s,
                              Eigen::VectorXd& q) {
  assert(factorized(active) && "condense() works on the supernodal factorization of the active set");
  const auto w = static_cast<Eigen::Index>(window.size());
  columns_.clear();
  for (const std::size_t r : window) {
    add_column(r, 1.0);
  }
  window_reach_ = std::make_shared<const SparseCholesky::Reach>(cholesky_->forward_columns(columns_));
  window_gram_ = window_reach_->gram();
  window_rows_.assign(window.begin(), window.end());
  if (!std::is_sorted(window_rows_.begin(), window_rows_.end())) window_rows_.clear();  // correct() searches it
  const Eigen::Map<const Eigen::MatrixXd> t(window_gram_.data(), w, w);
  Eigen::VectorXd penalty(w), gap(w), y0(w);
  for (Eigen::Index i = 0; i < w; ++i) {
    const std::size_t r = window[static_cast<std::size_t>(i)];
    penalty[i] = active[r] ? rows_[r].rho : 0.0;
    gap[i] = value(r, u);
    y0[i] = force[r] + penalty[i] * gap[i];
  }
  const Eigen::MatrixXd m = Eigen::MatrixXd::Identity(w, w) - t * penalty.asDiagonal();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(m);
  s = lu.solve(t);
  s = 0.5 * (s + s.transpose()).eval();
  q = lu.solve(gap - t * y0);
  return s.allFinite() && q.allFinite();
}

void ConstraintRows::refine_equilibrium(std::span<const double> values, std::span<const double> rhs,
                                        std::span<const std::uint8_t> active, std::span<double> force,
                                        std::span<double> u, std::span<const std::uint8_t> loaded) {
  assert(cholesky_ != nullptr && "hold() before refine_equilibrium()");
  // r = f + C_L^T force - K u, K symmetric from its upper triangle.
  std::copy(rhs.begin(), rhs.end(), b_.begin());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (active[r] || (!loaded.empty() && loaded[r])) add_load(r, force[r], b_);
  }
  for (Index j = 0; j < pattern_.n; ++j) {
    for (Index k = pattern_.colptr[j]; k < pattern_.colptr[j + 1]; ++k) {
      const Index i = pattern_.rowind[k];
      b_[i] -= values[k] * u[j];
      if (i != j) b_[j] -= values[k] * u[i];
    }
  }
  std::vector<double> du(u.size());
  solve_held(b_, du);
  for (std::size_t j = 0; j < u.size(); ++j) u[j] += du[j];
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (!active[r]) continue;
    double c_du = 0.0;
    for (const Entry& e : entries(r)) c_du += e.coefficient * du[e.equation];
    force[r] -= rows_[r].rho * c_du;
  }
}

double ConstraintRows::scale(double length, std::span<const double> u) {
  double scale = length;
  for (const double x : u) scale = std::max(scale, std::abs(x));
  return scale;
}

double ConstraintRows::multipliers(std::span<const double> rhs, std::span<const std::uint8_t> active,
                                   std::span<double> force, std::span<double> u, double length, int& iterations,
                                   const DependentLoad& dependent, const Decided& decided) {
  assert(cholesky_ != nullptr && "hold() before multipliers()");
  double previous = std::numeric_limits<double>::infinity();
  double worst = 0.0;
  int stalled = 0;
  for (int m = 0; m < max_multiplier_iterations; ++m) {
    // K_A u = f + p + C_A^T (lambda - rho g0): the penalty's pull toward g = 0 plus the forces so far.
    std::copy(rhs.begin(), rhs.end(), b_.begin());
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      if (active[r]) add_load(r, force[r] - rows_[r].rho * rows_[r].g0, b_);
    }
    const double moved = dependent ? dependent(force, b_) : 0.0;
    solve_held(b_, u);
    ++iterations;
    // lambda <- lambda - rho g(u). With the new lambda, K u = f + p + C_A^T lambda holds exactly: u is
    // in equilibrium with the updated forces, and g_A is what is left to remove.
    worst = moved;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      if (!active[r]) continue;
      const double g = value(r, u);
      force[r] -= rows_[r].rho * g;
      worst = std::max(worst, std::abs(g));
    }
    if (!std::isfinite(worst)) throw SolverError("the contact solve produced non-finite displacements");
    if (worst <= round_off * scale(length, u)) break;
    if (decided && decided(worst)) break;
    // Below round-off nothing more can be gained: stop when two steps in a row fail to halve it.
    stalled = worst > 0.5 * previous ? stalled + 1 : 0;
    if (stalled >= 2) break;
    previous = worst;
  }
  return worst;
}

}  // namespace saasgaps
