// saasgaps_thermal_bench: heat conduction on a mechanical mesh against one mechanical numeric
// factorization + solve of the same mesh, measured in the same run.
//
//   build/tests/bench/saasgaps_thermal_bench --dofs 1e5
//   build/tests/bench/saasgaps_thermal_bench --dofs 1e6 --repeat 1
//   build/tests/bench/saasgaps_thermal_bench --dofs 1e5 --family quad8
//
// The model is an n x n plane-strain block of SAAS quads (2 (n + 1)^2 - 2 (n + 1) mechanical
// unknowns: the bottom row is held), fixed at the bottom and pressed on the top; its `thermal`
// section holds the bottom at 100, cools the top through a film (h 50 to 20) and heats every element
// (a source), the sides insulated: one temperature per node, (n + 1)^2 - (n + 1) unknowns.
// --family (tri3 excepted) meshes the block with that family instead (add_quadratic_grid, n chosen
// for about --dofs mechanical unknowns); the default, saas, is the grid above.
//
// Reported, each the best of --repeat runs, interleaved so that a busy machine disturbs all alike:
// - the baseline: one numeric factorization of the mechanical K (pattern and symbolic analysis done
//   before, as in every later gap or contact iteration) and one solve;
// - the steady conduction: solve_steady_conduction(), the whole call from the model (building the
//   conduction pattern, its symbolic analysis, assembly, factorization, solve, element fluxes);
//   and, from ThermalSystem and SparseCholesky directly, its stages: the numeric part (assembly +
//   factorization + solve) is what a conduction solve costs once its analysis exists, which is the
//   counterpart of the baseline;
// - the transient cost per time step once the factorization is reused: solve_transient_conduction()
//   of 1 + steps steps minus that of 1 step (same model, constant k, c and step, so one
//   factorization in both), divided by steps; and, from ThermalSystem, a step's whole assembly
//   (keeping the load parts) against its rhs-only assembly (ThermalSystem::assemble_rhs).
// Ratios: steady (numeric, and whole call) / baseline; per step / one mechanical factorization.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "solver/thermal/thermal_system.hpp"
#include "support/mesh_builder.hpp"

#include "peak_memory.hpp"
#include "stopwatch.hpp"

using namespace saasgaps;

namespace {

using saasgaps::bench::peak_rss_mib;
using saasgaps::bench::timed;

/// The block of n x n cells of `type`, its mechanical loads and its thermal section (steady;
/// transient() makes it transient).
Model conducting_block(int n, ElementType type) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  Material steel = testing::isotropic_material(1, 30.0e6, 0.3, 6.5e-6);
  steel.table[0].k1 = steel.table[0].k2 = steel.table[0].k3 = 0.6;  // power / length / temperature
  steel.table[0].c = 0.11;
  steel.density = 0.28;
  steel.conducts = steel.stores_heat = true;
  m.materials = {steel};
  const auto square = [](double s, double t) { return Vec2(s, t); };
  Thermal& thermal = m.thermal.emplace();
  ThermalBoundary held{ThermalBoundary::Kind::temperature, {}, 100.0, 0.0};
  ThermalBoundary film{ThermalBoundary::Kind::film, {}, 50.0, 20.0};
  if (type != ElementType::saas) {
    const testing::QuadraticGrid g = testing::add_quadratic_grid(m, type, n, n, square, 0);
    for (const int node : g.row_nodes(0)) testing::constrain(m, node, 0.0, 0.0);
    held.edges = testing::quadratic_grid_side(m, g, 'b');
    film.edges = testing::quadratic_grid_side(m, g, 't');
    for (const ThermalEdge& e : film.edges) m.loads.pressures.push_back({e.element, e.node_a, e.node_b, 1000.0, 0.0});
  }
  const testing::Grid g = type == ElementType::saas ? testing::add_grid(m, n, n, square, 0) : testing::Grid{};
  // add_grid numbers element (i, j) as i + n j.
  for (int i = 0; i < g.ni; ++i) {
    testing::constrain(m, g.at(i, 0), 0.0, 0.0);
    held.edges.push_back({i, g.at(i, 0), g.at(i + 1, 0)});
    const int top = (n - 1) * n + i;
    m.loads.pressures.push_back({top, g.at(i, n), g.at(i + 1, n), 1000.0, 0.0});
    film.edges.push_back({top, g.at(i, n), g.at(i + 1, n)});
  }
  if (type == ElementType::saas) testing::constrain(m, g.at(n, 0), 0.0, 0.0);
  thermal.boundary = {held, film};
  thermal.sources = {{0, 200.0}};
  thermal.initial_temperature = 20.0;
  testing::fill_temperatures(m, 20.0);
  return m;
}

/// The block's transient run: `steps` steps of dt, an output after the first and at the end.
Model transient(const Model& steady, int steps, double dt) {
  Model m = steady;
  Thermal& thermal = *m.thermal;
  thermal.type = ThermalType::transient;
  thermal.time_step = dt;
  thermal.end_time = steps * dt;
  thermal.output_times = steps > 1 ? std::vector<double>{dt, steps * dt} : std::vector<double>{dt};
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times heat conduction on a mechanical mesh against one mechanical factorization + solve"};
  double target_dofs = 1.0e5;
  int repeat = 3;
  int steps = 20;
  std::string family_name = "saas";
  app.add_option("--dofs", target_dofs, "Approximate number of mechanical degrees of freedom")
      ->check(CLI::Range(100.0, 1.0e8));
  app.add_option("--repeat", repeat, "Runs of each timing; the best is reported")->check(CLI::Range(1, 100));
  app.add_option("--steps", steps, "Time steps of the longer transient run, beyond the first")
      ->check(CLI::Range(1, 100000));
  app.add_option("--family", family_name, "Element family of the block: saas, quad4i, tri6, quad8 or quad9")
      ->check(CLI::IsMember({"saas", "quad4i", "tri6", "quad8", "quad9"}));
  CLI11_PARSE(app, argc, argv);
  const ElementType type = *element_type_names.value(family_name);

  // Nodes per cell: the node count of an n x n block is a n^2 + b n + c, and a is its second
  // difference over n = 10, 20, 30 divided by 200 (1 for saas, so n = sqrt(dofs / 2) as before).
  const auto nodes = [type](int cells) { return static_cast<double>(conducting_block(cells, type).nodes.size()); };
  const double nodes_per_cell = (nodes(30) - 2.0 * nodes(20) + nodes(10)) / 200.0;
  const int n = std::max(2, static_cast<int>(std::lround(std::sqrt(target_dofs / (2.0 * nodes_per_cell)))));
  const Model m = conducting_block(n, type);
  // A step of about a tenth of the time heat needs to cross one element: short enough that every
  // step changes the temperatures everywhere near the boundaries.
  const double h = 1.0 / n;
  const Material& steel = m.materials[0];
  const double dt = 0.1 * h * h * steel.density * steel.table[0].c / steel.table[0].k1;
  const Model short_run = transient(m, 1, dt);
  const Model long_run = transient(m, 1 + steps, dt);

  // The mechanical baseline.
  DofMap dofs(m);
  StiffnessSystem system(m, dofs);
  const SolidMaterials materials(m);
  const MaterialState state = materials.initial();
  system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
  SparseCholesky cholesky(system.pattern(), dofs.node_of_equation());
  std::vector<double> u(static_cast<std::size_t>(dofs.size()));
  cholesky.factorize(system.values());  // first touch of the factor's memory, not timed

  // The conduction system's stages, as ConductionSolver (thermal_analysis.cpp) runs them.
  std::optional<ThermalSystem> conduction;
  const double thermal_pattern_s = timed([&] { conduction.emplace(m); });
  std::optional<SparseCholesky> thermal_cholesky, metis_cholesky;
  const double thermal_analysis_s = timed(
      [&] { thermal_cholesky.emplace(conduction->pattern(), std::span<const Index>{}, nullptr, FillOrdering::minimum_degree); });
  const double metis_analysis_s =
      timed([&] { metis_cholesky.emplace(conduction->pattern(), conduction->dofs().node_of_equation()); });
  std::vector<double> values(static_cast<std::size_t>(conduction->pattern().nnz()));
  std::vector<double> rhs(static_cast<std::size_t>(conduction->dofs().size())), x(rhs.size());
  const std::vector<double> reference(m.nodes.size(), m.reference_temperature);
  const std::vector<Conductivity> k = conduction->conductivities(reference);
  conduction->assemble(k, 0.0, {}, {}, {}, reference, values, rhs);
  thermal_cholesky->factorize(values);  // first touch
  metis_cholesky->factorize(values);

  double factorize_s = 1e300, solve_s = 1e300;
  double steady_s = 1e300, assemble_s = 1e300, thermal_factorize_s = 1e300, thermal_solve_s = 1e300;
  double short_s = 1e300, long_s = 1e300, metis_factorize_s = 1e300;
  // A time step's assembly: whole (matrix and rhs, keeping the load parts) and rhs only.
  const double inverse_dt = 1.0 / dt;
  ConductionLoads loads;
  double step_assemble_s = 1e300, rhs_only_s = 1e300;
  ThermalResult steady, shorter, longer;
  for (int r = 0; r < repeat; ++r) {
    factorize_s = std::min(factorize_s, timed([&] { cholesky.factorize(system.values()); }));
    solve_s = std::min(solve_s, timed([&] { cholesky.solve(system.rhs(), u); }));
    steady_s = std::min(steady_s, timed([&] { steady = solve_steady_conduction(m); }));
    assemble_s = std::min(assemble_s, timed([&] { conduction->assemble(k, 0.0, {}, {}, {}, reference, values, rhs); }));
    thermal_factorize_s = std::min(thermal_factorize_s, timed([&] { thermal_cholesky->factorize(values); }));
    thermal_solve_s = std::min(thermal_solve_s, timed([&] { thermal_cholesky->solve(rhs, x); }));
    metis_factorize_s = std::min(metis_factorize_s, timed([&] { metis_cholesky->factorize(values); }));
    step_assemble_s = std::min(step_assemble_s, timed([&] {
      conduction->assemble(k, inverse_dt, reference, {}, {}, reference, values, rhs, &loads);
    }));
    rhs_only_s = std::min(rhs_only_s, timed([&] { conduction->assemble_rhs(k, inverse_dt, reference, {}, {}, loads, rhs); }));
    short_s = std::min(short_s, timed([&] { shorter = solve_transient_conduction(short_run); }));
    long_s = std::min(long_s, timed([&] { longer = solve_transient_conduction(long_run); }));
  }
  const double baseline = factorize_s + solve_s;
  const double numeric = assemble_s + thermal_factorize_s + thermal_solve_s;
  const double per_step = (long_s - short_s) / steps;
  double T_max = 0.0;
  for (double T : steady.T) T_max = std::max(T_max, T);

  std::printf("model: plane-strain block, %d x %d %s cells, %lld mechanical unknowns (nnz(L) %.3g, %.3g Gflop per "
              "factorization), %lld conduction unknowns (nnz(L) %.3g, %.3g Gflop)\n",
              n, n, family_name.c_str(), static_cast<long long>(dofs.size()), cholesky.factor_nonzeros(), cholesky.factor_flops() / 1e9,
              static_cast<long long>(conduction->dofs().size()), thermal_cholesky->factor_nonzeros(),
              thermal_cholesky->factor_flops() / 1e9);
  std::printf("%-60s %10.4f\n", "mechanical numeric factorization", factorize_s);
  std::printf("%-60s %10.4f\n", "mechanical solve", solve_s);
  std::printf("%-60s %10.4f\n", "conduction pattern (ThermalSystem), once", thermal_pattern_s);
  std::printf("%-60s %10.4f\n", "conduction symbolic analysis (AMD, as solved), once", thermal_analysis_s);
  std::printf("%-60s %10.4f\n", "  for comparison: METIS on the node graph, once", metis_analysis_s);
  std::printf("%-60s %10.4f\n", "  for comparison: numeric factorization in METIS order", metis_factorize_s);
  std::printf("  nnz(L) and Gflop: AMD %.3g, %.3g; METIS %.3g, %.3g\n", thermal_cholesky->factor_nonzeros(),
              thermal_cholesky->factor_flops() / 1e9, metis_cholesky->factor_nonzeros(),
              metis_cholesky->factor_flops() / 1e9);
  std::printf("%-60s %10.4f\n", "conduction assembly", assemble_s);
  std::printf("%-60s %10.4f\n", "conduction numeric factorization", thermal_factorize_s);
  std::printf("%-60s %10.4f\n", "conduction solve", thermal_solve_s);
  std::printf("%-60s %10.4f\n", "steady conduction, whole solve_steady_conduction()", steady_s);
  std::printf("  passes %d, factorizations %d, largest T %.4g\n", steady.iterations, steady.factorizations, T_max);
  std::printf("%-60s %10.4f\n", "transient, 1 step (with pattern, analysis, factorization)", short_s);
  std::printf("%-60s %10.4f\n", "transient, more steps", long_s);
  std::printf("  steps %d and %d, factorizations %d and %d, dt %.3g\n", shorter.time_steps, longer.time_steps,
              shorter.factorizations, longer.factorizations, dt);
  std::printf("%-60s %10.5f\n", "transient, per step once factorized (difference / steps)", per_step);
  std::printf("%-60s %10.5f\n", "  a step's whole assembly (matrix, rhs, load parts kept)", step_assemble_s);
  std::printf("%-60s %10.5f\n", "  a step's rhs-only assembly (from the load parts)", rhs_only_s);
  std::printf("ratio steady numeric (assembly + factorization + solve) / mechanical (factorization + solve): %.3f\n",
              numeric / baseline);
  std::printf("ratio steady whole call / mechanical (factorization + solve): %.3f\n", steady_s / baseline);
  std::printf("ratio transient step / mechanical factorization: %.4f\n", per_step / factorize_s);
  std::printf("peak RSS of the process: %.0f MiB\n", peak_rss_mib());
  return 0;
}
