// ThermalSystem::assemble_rhs, the right-hand side of a time step whose matrix is unchanged, against
// the whole assembly: the same bits, on a distorted axisymmetric block with every kind of load
// (a held edge lifted into the rhs, a film, a flux, a source, the capacity of the previous step).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver/thermal/thermal_system.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

Model heated_block(int n) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  Material mat = testing::isotropic_material(1, 30.0e6, 0.3, 6.5e-6);
  mat.table[0].k1 = 0.6;
  mat.table[0].k2 = 0.4;
  mat.table[0].c = 0.11;
  mat.density = 0.28;
  mat.conducts = mat.stores_heat = true;
  m.materials = {mat};
  // Distorted, away from the axis, with an angle between the material axes and (r, z).
  const testing::Grid g = testing::add_grid(
      m, n, n, [](double s, double t) { return Vec2(1.0 + s + 0.1 * std::sin(3.0 * t), t + 0.07 * s * s); }, 0);
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

TEST(ThermalSystem, RhsOnlyAssemblyHasTheWholeAssemblysBits) {
  const Model m = heated_block(6);
  const ThermalSystem system(m);
  const std::vector<double> start(m.nodes.size(), 20.0);
  const std::vector<Conductivity> k = system.conductivities(start);
  std::vector<double> values(static_cast<std::size_t>(system.pattern().nnz()));
  std::vector<double> rhs(static_cast<std::size_t>(system.dofs().size()));
  std::vector<ConductionLoadParts> loads;
  const double inverse_dt = 1.0 / 0.01;
  system.assemble(k, inverse_dt, start, {}, {}, start, values, rhs, &loads);
  ASSERT_EQ(loads.size(), m.elements.size());

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

}  // namespace
}  // namespace saasgaps
