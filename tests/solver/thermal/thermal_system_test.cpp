// ThermalSystem::assemble_rhs, the right-hand side of a time step whose matrix is unchanged, against
// the whole assembly: the same bits, on a distorted axisymmetric block with every kind of load
// (a held edge lifted into the rhs, a film, a flux, a source, the capacity of the previous step),
// of the report's quads and of every other family (their load parts kept as the report's are). And a
// quad8 transient run, which takes that path for every step after the first, against the same run
// reassembled and refactorized at every step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "solver/lac/sparse_cholesky.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "solver/thermal/thermal_system.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

Material heated_material() {
  Material mat = testing::isotropic_material(1, 30.0e6, 0.3, 6.5e-6);
  mat.table[0].k1 = 0.6;
  mat.table[0].k2 = 0.4;
  mat.table[0].c = 0.11;
  mat.density = 0.28;
  mat.conducts = mat.stores_heat = true;
  return mat;
}

/// Distorted, away from the axis (s, t in 0..1).
Vec2 distorted(double s, double t) { return Vec2(1.0 + s + 0.1 * std::sin(3.0 * t), t + 0.07 * s * s); }

Model heated_block(int n) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {heated_material()};
  // Distorted, away from the axis, with an angle between the material axes and (r, z).
  const testing::Grid g = testing::add_grid(m, n, n, distorted, 0);
  for (Element& el : m.elements) el.angle_deg = 30.0;
  Thermal& thermal = m.thermal.emplace();
  ThermalBoundary held{ThermalBoundary::Kind::temperature, {}, 100.0, 0.0};
  ThermalBoundary film{ThermalBoundary::Kind::film, {}, 50.0, 20.0};
  ThermalBoundary flux{ThermalBoundary::Kind::flux, {}, 7.5, 0.0};
  for (int i = 0; i < n; ++i) {
    held.edges.push_back({i, g.at(i, 0), g.at(i + 1, 0)});
    film.edges.push_back({(n - 1) * n + i, g.at(i, n), g.at(i + 1, n)});
    flux.edges.push_back({i * n + n - 1, g.at(n, i), g.at(n, i + 1)});  // element (n - 1, i)
  }
  thermal.boundary = {held, film, flux};
  thermal.sources = {{0, 200.0}};
  thermal.type = ThermalType::transient;
  testing::fill_temperatures(m, 20.0);
  return m;
}

/// The same block of n x n cells of another family (curved edges: the mid-side nodes on the map).
Model heated_family_block(ElementType type, int n) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {heated_material()};
  const testing::QuadraticGrid g = testing::add_quadratic_grid(m, type, n, n, distorted, 0);
  for (Element& el : m.elements) el.angle_deg = 30.0;
  Thermal& thermal = m.thermal.emplace();
  thermal.boundary = {{ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, g, 'b'), 100.0, 0.0},
                      {ThermalBoundary::Kind::film, testing::quadratic_grid_side(m, g, 't'), 50.0, 20.0},
                      {ThermalBoundary::Kind::flux, testing::quadratic_grid_side(m, g, 'r'), 7.5, 0.0}};
  thermal.sources = {{0, 200.0}};
  thermal.type = ThermalType::transient;
  testing::fill_temperatures(m, 20.0);
  return m;
}

/// assemble_rhs against assemble on a later step of m with the same k, c and dt.
void expect_rhs_only_assembly_has_the_whole_assemblys_bits(const Model& m) {
  const ThermalSystem system(m);
  const std::vector<double> start(m.nodes.size(), 20.0);
  const std::vector<Conductivity> k = system.conductivities(start);
  std::vector<double> values(static_cast<std::size_t>(system.pattern().nnz()));
  std::vector<double> rhs(static_cast<std::size_t>(system.dofs().size()));
  ConductionLoads loads;
  const double inverse_dt = 1.0 / 0.01;
  system.assemble(k, inverse_dt, start, {}, {}, start, values, rhs, &loads);
  ASSERT_EQ(loads.size(), m.elements.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    if (m.elements[e].type != ElementType::saas) {
      // Every element's own C and source weights, one per node.
      EXPECT_EQ(loads.capacity(e).rows(), m.elements[e].node_count);
      EXPECT_EQ(loads.source(e).size(), m.elements[e].node_count);
    }
  }

  // A later step: other previous temperatures, the same k, c and dt.
  std::vector<double> previous(m.nodes.size());
  for (std::size_t i = 0; i < previous.size(); ++i) previous[i] = 20.0 + 13.0 * std::sin(0.7 * static_cast<double>(i));
  std::vector<double> whole_values(values.size()), whole_rhs(rhs.size()), only_rhs(rhs.size(), -1.0);
  system.assemble(k, inverse_dt, previous, {}, {}, previous, whole_values, whole_rhs);
  system.assemble_rhs(k, inverse_dt, previous, {}, {}, loads, only_rhs);
  EXPECT_EQ(whole_values, values);  // the matrix did not change
  EXPECT_EQ(only_rhs, whole_rhs);   // bit for bit
  EXPECT_NE(whole_rhs, rhs);        // and the rhs did
}

TEST(ThermalSystem, RhsOnlyAssemblyHasTheWholeAssemblysBits) { expect_rhs_only_assembly_has_the_whole_assemblys_bits(heated_block(6)); }

class ThermalSystemFamily : public ::testing::TestWithParam<ElementType> {};

TEST_P(ThermalSystemFamily, RhsOnlyAssemblyHasTheWholeAssemblysBits) {
  expect_rhs_only_assembly_has_the_whole_assemblys_bits(heated_family_block(GetParam(), 4));
}

INSTANTIATE_TEST_SUITE_P(Families, ThermalSystemFamily,
                         ::testing::Values(ElementType::tri6, ElementType::quad8, ElementType::quad9, ElementType::quad4i),
                         [](const ::testing::TestParamInfo<ElementType>& type) {
                           return std::string(element_type_names.name(type.param));
                         });

TEST(ThermalSystem, Quad8TransientRunOnTheRhsOnlyPathMatchesTheWholeReassembly) {
  Model m = heated_family_block(ElementType::quad8, 6);
  Thermal& thermal = *m.thermal;
  thermal.initial_temperature = 20.0;
  thermal.time_step = 0.01;
  thermal.end_time = 0.2;
  thermal.output_times = {0.05, 0.1, 0.2};
  const ThermalResult fast = solve_transient_conduction(m);
  ASSERT_EQ(fast.time_steps, 20);
  EXPECT_EQ(fast.factorizations, 1);
  EXPECT_EQ(fast.rhs_only_solves, 19);  // every step after the first: the rhs only

  // The same steps, each assembled whole and factorized anew.
  const ThermalSystem system(m);
  SparseCholesky cholesky(system.pattern(), {}, nullptr, FillOrdering::minimum_degree);
  std::vector<double> values(static_cast<std::size_t>(system.pattern().nnz()));
  std::vector<double> rhs(static_cast<std::size_t>(system.dofs().size())), x(rhs.size());
  std::vector<double> T(m.nodes.size(), thermal.initial_temperature);
  std::vector<std::vector<double>> history;
  for (int step = 1; step <= 20; ++step) {
    system.assemble(system.conductivities(T), 1.0 / thermal.time_step, T, {}, {}, T, values, rhs);
    cholesky.factorize(values);
    cholesky.solve(rhs, x);
    T = system.node_temperatures(x);
    if (step == 5 || step == 10 || step == 20) history.push_back(T);
  }
  ASSERT_EQ(fast.history.size(), history.size());
  double largest = 0.0, heating = 0.0;
  for (std::size_t k = 0; k < history.size(); ++k) {
    for (std::size_t n = 0; n < T.size(); ++n) {
      largest = std::max(largest, std::abs(fast.history[k][n] - history[k][n]));
      heating = std::max(heating, std::abs(history[k][n] - history.front()[n]));
    }
  }
  std::printf("quad8 transient, rhs-only steps against whole reassembly: largest difference %.3e; largest change "
              "from the first output time %.4g\n", largest, heating);
  EXPECT_EQ(largest, 0.0);  // the same rhs bits and the same factor: the same temperatures, bit for bit
  EXPECT_GT(heating, 1.0);  // and the steps are not all alike
}

}  // namespace
}  // namespace saasgaps
