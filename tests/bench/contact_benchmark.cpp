// saasgaps_contact_bench: the exact contact mode (gaps.method = "exact") against one numeric
// factorization + solve of the same matrix, measured in the same run.
//
//   build/tests/bench/saasgaps_contact_bench --dofs 1.5e5 --gaps 600
//   build/tests/bench/saasgaps_contact_bench --dofs 1e6 --gaps 1600 --repeat 1
//   build/tests/bench/saasgaps_contact_bench --dofs 1.5e5 --gaps 600 --eccentricity 3
//
// The model is the ring fit of tests/verification/exact_lame_test.cpp at scale: a quarter annulus
// heated inside a quarter annulus across a radial gap, plane strain, symmetry on both axes, with
// `gaps` gap elements around the interface (every pair ends in contact). Reported: the baseline (one
// numeric factorization of K with the gaps at the floor modulus, and one solve), the exact contact
// solve from a cold start (every pair active at first) with its active sets and multiplier solves,
// and the ratio of the two; with --end-to-end also the whole solve() of the model.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "solver/analysis/analysis.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/contact/exact_contact.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "support/ring_fit.hpp"

#include "stopwatch.hpp"

using namespace saasgaps;

namespace {

using saasgaps::bench::timed;

Model ring_fit(int radial, int hoop, double eccentricity) {
  Model m = testing::quarter_ring_fit(AnalysisType::plane_strain, radial, hoop, eccentricity);
  m.gaps->method = GapMethod::exact;
  m.gaps->tensile_schedule = {1.0};
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times the exact contact solve against one factorization + solve of the same matrix"};
  double target_dofs = 1.5e5;
  int hoop = 600;
  bool end_to_end = false;
  int repeat = 3;
  double eccentricity = 0.0;
  app.add_option("--eccentricity", eccentricity,
                 "Widen the gap to (1 + e) delta at 90 degrees: contact over part of the interface")
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--repeat", repeat, "Runs of each timing; the best is reported")->check(CLI::Range(1, 100));
  app.add_option("--dofs", target_dofs, "Approximate number of degrees of freedom")->check(CLI::Range(100.0, 1.0e8));
  app.add_option("--gaps", hoop, "Gap elements around the interface")->check(CLI::Range(2, 1000000));
  app.add_flag("--end-to-end", end_to_end, "Also time the whole solve() of the model");
  CLI11_PARSE(app, argc, argv);

  // 2 rings x (radial + 1) x (hoop + 1) nodes, 2 unknowns each.
  const int radial = std::max(1, static_cast<int>(std::lround(target_dofs / (4.0 * (hoop + 1)))) - 1);
  const Model m = ring_fit(radial, hoop, eccentricity);
  DofMap dofs(m);
  StiffnessSystem system(m, dofs);
  testing::assemble_with_gaps_at_floor(m, system);
  SparseCholesky cholesky(system.pattern(), dofs.node_of_equation());
  std::vector<double> u(static_cast<std::size_t>(dofs.size()));

  // The best of `repeat` runs of each, interleaved, so that a busy machine disturbs both alike.
  cholesky.factorize(system.values());  // first touch of the factor's memory, not timed
  ExactContact contact(m, dofs, system.pattern(), contact_pairs(m));
  ContactReport report;
  double factorize_s = 1e300, solve_s = 1e300, exact_s = 1e300;
  for (int r = 0; r < repeat; ++r) {
    factorize_s = std::min(factorize_s, timed([&] { cholesky.factorize(system.values()); }));
    solve_s = std::min(solve_s, timed([&] { cholesky.solve(system.rhs(), u); }));
    ContactState cold;
    exact_s = std::min(exact_s, timed([&] { report = contact.solve(cholesky, system.values(), system.rhs(), cold, u); }));
  }

  std::printf("model: quarter-annulus ring fit, %d x %d quads per ring, %lld unknowns, %zu gap elements, %zu node pairs, "
              "nnz(L) %.3g, %.3g Gflop per factorization\n",
              radial, hoop, static_cast<long long>(dofs.size()), m.gap_count(), contact.pairs().pairs.size(),
              cholesky.factor_nonzeros(), cholesky.factor_flops() / 1e9);
  std::printf("%-52s %10.3f\n", "numeric factorization", factorize_s);
  std::printf("%-52s %10.3f\n", "solve", solve_s);
  std::printf("%-52s %10.3f\n", "exact contact solve (cold start)", exact_s);
  std::printf("  active sets %d (factorizations %d, the others solved on a factorization held: corrected or updated), multiplier solves %d, pairs in contact %d, "
              "complementarity %.2e\n",
              report.active_set_iterations, report.factorizations, report.multiplier_iterations,
              report.pairs_in_contact, report.complementarity);
  std::printf("ratio exact contact / (factorization + solve): %.3f\n", exact_s / (factorize_s + solve_s));
  if (end_to_end) {
    const double whole_s = timed([&] { (void)solve(m); });
    std::printf("%-52s %10.3f\n", "end to end: solve() of the exact-mode model", whole_s);
  }
  return 0;
}
