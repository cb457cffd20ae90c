// saasgaps_friction_bench: the frictional contact solver (FrictionalContact) on Cattaneo-Mindlin at
// scale, against one numeric factorization + solve of the same matrix measured in the same run.
//
//   build/tests/bench/saasgaps_friction_bench --dofs 1e5 --increments 10
//
// The model is tests/support/friction_models.hpp's Cattaneo-Mindlin pair of bodies (plane strain,
// one material, node pairs on matching meshes, gap x^2 / 2R), the interface spacing chosen for about
// --dofs unknowns: pressed by a rigid platen (one increment), then sheared by Q rising to 0.75 mu P
// in --increments increments. Reported: the baseline (a numeric Cholesky factorization of K plus the
// contact penalties of both rows of every pair, and one solve), per increment the active sets, factorizations and
// solves, the total (best of --repeat runs, 3) as a multiple of the baseline; and, for the choice of method, an unsymmetric LU
// factorization (UMFPACK) of the same matrix, the cost a Newton step with the unsymmetric slip
// tangent would pay per active set.
#include <CLI/CLI.hpp>
#include <umfpack.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "solver/contact/frictional_contact.hpp"
#include "solver/lac/updatable_factor.hpp"
#include "support/friction_models.hpp"

#include "stopwatch.hpp"

using namespace saasgaps;

namespace {

using saasgaps::bench::timed;

/// The full (both triangles) CSC matrix of an upper-triangle symmetric one.
struct FullCsc {
  std::vector<long> colptr, rowind;
  std::vector<double> values;
};

FullCsc full_matrix(const CscPattern& upper, std::span<const double> values) {
  const auto n = static_cast<std::size_t>(upper.n);
  std::vector<long> count(n, 0);
  for (Index j = 0; j < upper.n; ++j) {
    for (Index k = upper.colptr[j]; k < upper.colptr[j + 1]; ++k) {
      ++count[j];
      if (upper.rowind[k] != j) ++count[upper.rowind[k]];
    }
  }
  FullCsc a;
  a.colptr.assign(n + 1, 0);
  for (std::size_t j = 0; j < n; ++j) a.colptr[j + 1] = a.colptr[j] + count[j];
  a.rowind.resize(a.colptr[n]);
  a.values.resize(a.colptr[n]);
  std::vector<long> next(a.colptr.begin(), a.colptr.end() - 1);
  for (Index j = 0; j < upper.n; ++j) {
    for (Index k = upper.colptr[j]; k < upper.colptr[j + 1]; ++k) {
      const Index i = upper.rowind[k];
      a.rowind[next[j]] = i;
      a.values[next[j]++] = values[k];
      if (i != j) {
        a.rowind[next[i]] = j;
        a.values[next[i]++] = values[k];
      }
    }
  }
  // Rows ascending within each column, as UMFPACK wants.
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<std::pair<long, double>> column;
    for (long k = a.colptr[j]; k < a.colptr[j + 1]; ++k) column.emplace_back(a.rowind[k], a.values[k]);
    std::sort(column.begin(), column.end());
    for (long k = a.colptr[j]; k < a.colptr[j + 1]; ++k) {
      a.rowind[k] = column[k - a.colptr[j]].first;
      a.values[k] = column[k - a.colptr[j]].second;
    }
  }
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times the frictional contact solve against one factorization + solve of the same matrix"};
  double target_dofs = 1.0e5;
  int increments = 10;
  double mu = 0.3;
  int repeat = 3;
  app.add_option("--dofs", target_dofs, "Approximate number of degrees of freedom")->check(CLI::Range(1000.0, 1.0e7));
  app.add_option("--increments", increments, "Increments of the shear")->check(CLI::Range(1, 1000));
  app.add_option("--mu", mu, "Coulomb coefficient")->check(CLI::Range(0.01, 10.0));
  app.add_option("--repeat", repeat, "Runs of the press and shear (the best is reported)")->check(CLI::Range(1, 20));
  CLI11_PARSE(app, argc, argv);

  // The spacing for about target_dofs unknowns (they grow like 1 / spacing^2 near the contact).
  double spacing = 0.1;
  testing::Cylinders c = testing::cylinders(0.18, spacing, 1.05);
  for (int k = 0; k < 30; ++k) {
    const double dofs = 4.0 * static_cast<double>(c.model.nodes.size()) / 2.0;
    if (std::abs(dofs / target_dofs - 1.0) < 0.15) break;
    spacing *= std::sqrt(dofs / target_dofs);
    c = testing::cylinders(0.18, spacing, 1.05);
  }
  testing::CoupledSystem system(c.model, c.pairs);
  const std::size_t points = c.pairs.pairs.size();
  FrictionalContact contact(c.model, system.dofs(), system.pattern(), c.pairs, std::vector<double>(points, mu));

  // The baseline: K plus the penalty rho c c^T of both rows of every pair (the matrix of the press
  // increment, every point sticking; K alone leaves the upper body free along r).
  std::vector<double> baseline(system.values().begin(), system.values().end());
  const CscPattern& pattern = system.pattern();
  for (std::size_t r = 0; r < contact.rows().size(); ++r) {
    const auto entries = contact.rows().entries(r);
    double k = 0.0;
    for (const auto& e : entries) k += e.coefficient * e.coefficient * baseline[pattern.find(e.equation, e.equation)];
    const double rho = ConstraintRows::penalty_factor * k;
    for (std::size_t x = 0; x < entries.size(); ++x) {
      for (std::size_t y = x; y < entries.size(); ++y) {
        baseline[pattern.find(entries[x].equation, entries[y].equation)] +=
            rho * entries[x].coefficient * entries[y].coefficient;
      }
    }
  }
  std::vector<double> u(static_cast<std::size_t>(system.dofs().size()), 0.0);
  const std::vector<double> f0 = system.rhs(testing::sheared(c, 0.0));
  system.cholesky().factorize(baseline);  // first touch of the factor's memory, not timed
  double factorize_s = 1e300, solve_s = 1e300;
  for (int r = 0; r < 3; ++r) {
    factorize_s = std::min(factorize_s, timed([&] { system.cholesky().factorize(baseline); }));
    solve_s = std::min(solve_s, timed([&] { system.cholesky().solve(f0, u); }));
  }
  std::printf("model: Cattaneo-Mindlin, interface spacing %.4g a, %lld unknowns, %zu node pairs, nnz(L) %.3g\n", spacing,
              static_cast<long long>(system.dofs().size()), points, system.cholesky().factor_nonzeros());
  std::printf("%-44s %10.3f s\n", "numeric Cholesky factorization (CHOLMOD)", factorize_s);
  std::printf("%-44s %10.3f s\n", "solve", solve_s);
  // What a rank-k-updated active set pays instead: the factor's conversion to simplicial form in
  // place (once per base set: ConstraintRows::hold_from keeps a copy of it while K and the touching
  // points are unchanged; the conversion consumes the factorization, so each run factorizes first),
  // the copy of the kept factor each increment starts from, and the solves on it.
  UpdatableFactor updatable;
  double copy_s = 1e300, simplicial_s = 1e300;
  for (int r = 0; r < 3; ++r) {
    system.cholesky().factorize(baseline);
    copy_s = std::min(copy_s, timed([&] { updatable.convert(system.cholesky()); }));
    simplicial_s = std::min(simplicial_s, timed([&] { updatable.solve(f0, u); }));
  }
  UpdatableFactor working;
  working.copy(updatable);  // first touch of its memory, not timed
  double recopy_s = 1e300;
  for (int r = 0; r < 3; ++r) recopy_s = std::min(recopy_s, timed([&] { working.copy(updatable); }));
  system.cholesky().factorize(baseline);  // supernodal again for what follows
  std::printf("%-44s %10.3f s\n", "simplicial conversion of the factor (for updates)", copy_s);
  std::printf("%-44s %10.3f s\n", "copy of the kept factor (each increment)", recopy_s);
  std::printf("%-44s %10.3f s\n", "simplicial solve", simplicial_s);

  // The unsymmetric alternative: UMFPACK's symbolic and numeric LU of the same matrix.
  const FullCsc a = full_matrix(pattern, baseline);
  const long n = system.dofs().size();
  void* symbolic = nullptr;
  void* numeric = nullptr;
  double control[UMFPACK_CONTROL];
  umfpack_dl_defaults(control);
  double lu_s = 1e300;
  const double symbolic_s = timed([&] {
    if (umfpack_dl_symbolic(n, n, a.colptr.data(), a.rowind.data(), a.values.data(), &symbolic, control, nullptr) != 0) {
      throw std::runtime_error("umfpack symbolic failed");
    }
  });
  for (int r = 0; r < 3; ++r) {
    lu_s = std::min(lu_s, timed([&] {
      if (numeric) umfpack_dl_free_numeric(&numeric);
      if (umfpack_dl_numeric(a.colptr.data(), a.rowind.data(), a.values.data(), symbolic, &numeric, control, nullptr) != 0) {
        throw std::runtime_error("umfpack numeric failed");
      }
    }));
  }
  umfpack_dl_free_numeric(&numeric);
  umfpack_dl_free_symbolic(&symbolic);
  std::printf("%-44s %10.3f s (symbolic %.3f s)\n", "numeric LU factorization (UMFPACK)", lu_s, symbolic_s);
  std::printf("ratio LU / Cholesky: %.2f\n", lu_s / factorize_s);

  // The run: press, then Q up to 0.75 mu P; `repeat` times, each with a solver of its own (no factor
  // kept from the run before), the best total against the best baseline (a shared machine's noise
  // only ever adds). The runs are identical but for the time: the counts are printed once.
  double total_s = 1e300;
  int factorizations = 0, solves = 0;
  for (int r = 0; r < repeat; ++r) {
    FrictionalContact run(c.model, system.dofs(), system.pattern(), c.pairs, std::vector<double>(points, mu));
    FrictionState state;
    FrictionReport report;
    double run_s = 0.0;
    factorizations = solves = 0;
    run_s += timed([&] { report = run.solve(system.cholesky(), system.values(), f0, state, u); });
    finish_increment(state);
    double P = 0.0;
    for (double force : state.normal_force) P += force;
    factorizations += report.factorizations;
    solves += report.multiplier_iterations;
    if (r == 0) {
      std::printf("press: P %.4g, %d in contact, %d active sets, %d factorizations, %d solves\n", P, report.in_contact,
                  report.active_set_iterations, report.factorizations, report.multiplier_iterations);
    }
    for (int k = 1; k <= increments; ++k) {
      const std::vector<double> f = system.rhs(testing::sheared(c, 0.75 * mu * P * k / increments));
      run_s += timed([&] { report = run.solve(system.cholesky(), system.values(), f, state, u); });
      finish_increment(state);
      factorizations += report.factorizations;
      solves += report.multiplier_iterations;
      if (r > 0) continue;
      std::printf("increment %2d: stick %d slip %d, %d active sets, %d factorizations, %d solves, residuals %.1e %.1e\n",
                  k, report.sticking, report.slipping, report.active_set_iterations, report.factorizations,
                  report.multiplier_iterations, report.complementarity, report.friction_residual);
    }
    std::printf("run %d: %.3f s\n", r + 1, run_s);
    total_s = std::min(total_s, run_s);
  }
  const int solved = increments + 1;
  std::printf("total %.3f s (best of %d) over %d increments: %d factorizations, %d solves; %.2f factorization + solve "
              "equivalents per increment\n",
              total_s, repeat, solved, factorizations, solves, total_s / (factorize_s + solve_s) / solved);
  return 0;
}
