// saasgaps_bench: times the solver's stages on a generated structured plane-strain model.
//
//   build/tests/bench/saasgaps_bench --dofs 1000000 [--gaps] [--baseline]
//
// The model is an n x n block of SAAS quads, fixed at the bottom, pressed on the top, heated; with
// --gaps it is cut in two at mid height by a row of gap elements. Reported: pattern construction,
// assembly, symbolic analysis, numeric factorization (first, and repeated in the same factor object),
// solve, one gap iteration (gap patch + numeric factorization + solve), peak memory; and ratios
// against baselines measured in the same run: assembly / factorization, gap iteration /
// factorization, and (with --baseline) our scatter assembly against Eigen's triplet assembly.
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <Eigen/SparseCore>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis.hpp"
#include "dof_map.hpp"
#include "element_data.hpp"
#include "gap_closure.hpp"
#include "material_state.hpp"
#include "sparse_cholesky.hpp"
#include "stiffness_system.hpp"
#include "support/mesh_builder.hpp"

using namespace saasgaps;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Runs f once and returns its wall time.
template <class F>
double timed(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return seconds_since(start);
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

Model block_model(int n, bool with_gaps) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, 30.0e6, 0.3, 6.5e-6)};
  const double h = 1.0 / n;
  if (!with_gaps) {
    const testing::Grid g = testing::add_grid(m, n, n, [](double s, double t) { return Vec2(s, t); }, 0);
    for (int i = 0; i <= n; ++i) testing::constrain(m, g.at(i, 0), 0.0, 0.0);
    for (int i = 0; i < n; ++i) m.loads.pressures.push_back({(n - 1) * n + i, g.at(i, n), g.at(i + 1, n), 1000.0, 0.0});
  } else {
    // Two half blocks, the upper one resting on the lower through a row of gap elements 1 % of an
    // element thick.
    const int lower_rows = n / 2, upper_rows = n - lower_rows;
    const double gap = 0.01 * h;
    const testing::Grid lower = testing::add_grid(
        m, n, lower_rows, [&](double s, double t) { return Vec2(s, t * lower_rows * h); }, 0);
    const int upper_first = static_cast<int>(m.elements.size());
    const testing::Grid upper = testing::add_grid(
        m, n, upper_rows, [&](double s, double t) { return Vec2(s, lower_rows * h + gap + t * upper_rows * h); }, 0);
    std::vector<int> below, above;
    for (int i = 0; i <= n; ++i) {
      below.push_back(lower.at(i, lower_rows));
      above.push_back(upper.at(i, 0));
    }
    testing::add_gap_row(m, below, above, [](int) { return 90.0; });
    m.gaps->initial_modulus = 100.0;
    m.gaps->tensile_schedule = {1.0};
    for (int i = 0; i <= n; ++i) testing::constrain(m, lower.at(i, 0), 0.0, 0.0);
    // Hold the upper block sideways at one corner so the gaps' negligible shear is not all that holds it.
    testing::constrain(m, upper.at(0, upper_rows), 0.0, std::nullopt);
    for (int i = 0; i < n; ++i) {
      m.loads.pressures.push_back(
          {upper_first + (upper_rows - 1) * n + i, upper.at(i, upper_rows), upper.at(i + 1, upper_rows), 1000.0, 0.0});
    }
  }
  testing::fill_temperatures(m, 100.0);
  return m;
}

/// Eigen's triplet assembly of the same element matrices: the textbook baseline.
double triplet_assembly_seconds(const Model& m, const DofMap& dofs, const SolidMaterials& materials,
                                const MaterialState& state) {
  return timed([&] {
    std::vector<Eigen::Triplet<double, Index>> triplets;
    triplets.reserve(m.elements.size() * 36);
    for (std::size_t e = 0; e < m.elements.size(); ++e) {
      const ElementMatrices em = element_matrices(solid_element_data(m, e, materials.law(e, state)));
      const auto eq = dofs.element_equations(m.elements[e].nodes, 4);
      for (const LocalPair& p : upper_pairs) {
        if (eq[p.a] >= 0 && eq[p.b] >= 0) {
          triplets.emplace_back(std::min(eq[p.a], eq[p.b]), std::max(eq[p.a], eq[p.b]), em.K(p.a, p.b));
        }
      }
    }
    Eigen::SparseMatrix<double, Eigen::ColMajor, Index> K(dofs.size(), dofs.size());
    K.setFromTriplets(triplets.begin(), triplets.end());
  });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times the SAASGAPS solver stages on a generated structured plane-strain model"};
  double target_dofs = 1.0e5;
  bool with_gaps = false;
  bool baseline = false;
  bool end_to_end = false;
  app.add_option("--dofs", target_dofs, "Approximate number of degrees of freedom")->check(CLI::Range(100.0, 1.0e8));
  app.add_flag("--gaps", with_gaps, "Cut the block by a row of gap elements and time a gap iteration");
  app.add_flag("--baseline", baseline, "Also time Eigen's triplet assembly (after the peak memory reading)");
  app.add_flag("--end-to-end", end_to_end,
               "Also time one whole iteration as saasgaps solve runs it (fresh objects; symbolic analysis "
               "beside the assembly; stress recovery)");
  CLI11_PARSE(app, argc, argv);

  const int n = std::max(2, static_cast<int>(std::lround(std::sqrt(target_dofs / 2.0))) - 1);
  const Model m = block_model(n, with_gaps);

  std::vector<double> u;
  double pattern_s = 0, assembly_s = 0, symbolic_s = 0, first_numeric_s = 0, numeric_s = 0, solve_s = 0,
         gap_iteration_s = 0;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<StiffnessSystem> system;
  const SolidMaterials materials(m);
  const MaterialState state = materials.initial();
  pattern_s = timed([&] {
    dofs = std::make_unique<DofMap>(m);
    system = std::make_unique<StiffnessSystem>(m, *dofs);
  });
  SolidMaterials::LawMemo memo;
  assembly_s = timed([&] { system->assemble_solids([&](std::size_t e) { return materials.law(e, state, memo); }); });

  std::unique_ptr<GapClosure> gaps;
  GapModuli moduli;
  if (with_gaps) {
    gaps = std::make_unique<GapClosure>(*m.gaps);
    moduli = gaps->initial();
    system->assemble_gaps([&](std::size_t g) { return gaps->law(g, moduli, m.analysis); });
  }
  std::unique_ptr<SparseCholesky> cholesky;
  symbolic_s = timed([&] { cholesky = std::make_unique<SparseCholesky>(system->pattern(), dofs->node_of_equation()); });
  first_numeric_s = timed([&] { cholesky->factorize(system->values()); });
  numeric_s = timed([&] { cholesky->factorize(system->values()); });
  u.resize(static_cast<std::size_t>(dofs->size()));
  solve_s = timed([&] { cholesky->solve(system->rhs(), u); });
  if (with_gaps) {
    // One iteration of section II when only gap moduli change: patch, refactor, solve.
    for (double& e : moduli.normal) e *= 3.0;
    gap_iteration_s = timed([&] {
      system->assemble_gaps([&](std::size_t g) { return gaps->law(g, moduli, m.analysis); });
      cholesky->factorize(system->values());
      cholesky->solve(system->rhs(), u);
    });
  }
  const double peak = peak_rss_mib();

  std::printf("model: %d x %d SAAS quads%s, %zu nodes, %lld unknowns, nnz(K upper) %lld, nnz(L) %.3g, %.3g Gflop per factorization, ordering %s\n",
              n, n, with_gaps ? " cut by a row of gap elements" : "", m.nodes.size(),
              static_cast<long long>(dofs->size()), static_cast<long long>(system->pattern().nnz()),
              cholesky->factor_nonzeros(), cholesky->factor_flops() / 1e9, cholesky->ordering());
  std::printf("%-44s %10s\n", "stage", "seconds");
  std::printf("%-44s %10.3f\n", "pattern and scatter map (once per model)", pattern_s);
  std::printf("%-44s %10.3f\n", "assembly (solid elements)", assembly_s);
  std::printf("%-44s %10.3f\n", "symbolic analysis (once per model)", symbolic_s);
  std::printf("%-44s %10.3f\n", "numeric factorization, first", first_numeric_s);
  std::printf("%-44s %10.3f\n", "numeric factorization, repeated", numeric_s);
  std::printf("%-44s %10.3f\n", "solve", solve_s);
  if (with_gaps) std::printf("%-44s %10.3f\n", "gap iteration (patch + factorize + solve)", gap_iteration_s);
  std::printf("%-44s %10.3f\n", "assemble + factor + solve (first time)", assembly_s + symbolic_s + first_numeric_s + solve_s);
  std::printf("%-44s %10.0f\n", "peak memory (MiB)", peak);
  std::printf("ratio assembly / repeated factorization: %.3f\n", assembly_s / numeric_s);
  if (with_gaps) std::printf("ratio gap iteration / repeated factorization: %.3f\n", gap_iteration_s / numeric_s);
  if (end_to_end) {
    ResumeOptions one_iteration;
    one_iteration.max_iterations = 1;
    const double first_iteration_s = timed([&] { (void)solve(m, nullptr, nullptr, one_iteration); });
    std::printf("%-44s %10.3f\n", "end to end: first iteration of solve()", first_iteration_s);
  }
  if (baseline) {
    const double triplet_s = triplet_assembly_seconds(m, *dofs, materials, state);
    std::printf("%-44s %10.3f\n", "baseline: Eigen triplet assembly", triplet_s);
    std::printf("ratio scatter assembly / triplet assembly: %.3f\n", assembly_s / triplet_s);
  }
  return 0;
}
