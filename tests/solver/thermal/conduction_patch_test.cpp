// Patch tests of the temperature field through the new assembly path (DofMap with one component,
// conduction_kernel, Assembler, SparseCholesky): a distorted patch of SAAS quads and triangles, its
// boundary held at a field that solves the conduction equation exactly and lies in the element
// space, must reproduce the field inside to round-off.
//
// Plane: any linear T = a + b r + c z solves div(k grad T) = 0 for a constant tensor k, rotated
// orthotropic included. Axisymmetric: the equation is (1/r) d/dr(r q_r) + dq_z/dz = 0 with
// q = -k grad T. T = a + c z gives q = -c k e_z, constant; it is a solution exactly when q_r = 0,
// i.e. k_rz = 0 (isotropic, or material axes along r and z). T linear in r is not: r q_r = -b k_rr r
// has (1/r) d/dr(...) = -b k_rr / r != 0, a source term; the solution with that boundary is not
// linear (the last test shows the axisymmetric weighting makes it differ).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "solver/assembly/assembler.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/thermal/conduction_kernel.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

/// A 4 x 3 patch on [1, 3] x [0, 1.5], interior nodes pushed off the grid, two quads split into
/// triangles (along different diagonals).
Model distorted_patch(AnalysisType analysis) {
  Model m;
  m.analysis = analysis;
  m.thickness = 0.4;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  const testing::Grid g = testing::add_grid(m, 4, 3, [](double s, double t) { return Vec2(1.0 + 2.0 * s, 1.5 * t); }, 0);
  for (int j = 1; j < 3; ++j) {
    for (int i = 1; i < 4; ++i) {
      Node& n = m.nodes[g.at(i, j)];
      n.r += 0.09 * std::sin(3.0 * i + j);
      n.z += 0.08 * std::cos(2.0 * i - j);
    }
  }
  for (std::size_t which : {std::size_t{0}, std::size_t{6}}) {
    Element& quad = m.elements[which];
    Element second = quad;
    second.id = 100 + static_cast<int>(which);
    second.node_count = 3;
    const auto q = quad.nodes;
    if (which == 0) {
      quad.nodes = {q[0], q[1], q[2], -1};
      second.nodes = {q[0], q[2], q[3], -1};
    } else {
      quad.nodes = {q[0], q[1], q[3], -1};
      second.nodes = {q[1], q[2], q[3], -1};
    }
    quad.node_count = 3;
    m.elements.push_back(second);
  }
  return m;
}

bool on_boundary(const Node& n) { return n.r == 1.0 || n.r == 3.0 || n.z == 0.0 || n.z == 1.5; }

/// Solves the conduction problem with T prescribed on the boundary; returns T at every node.
std::vector<double> solve_temperature(const Model& m, const Conductivity& k,
                                      const std::function<double(double, double)>& boundary) {
  std::vector<int> ids;
  std::vector<DofMap::Prescribed> fixed;
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) {
    ids.push_back(m.nodes[n].id);
    if (on_boundary(m.nodes[n])) fixed.push_back({n, 0, boundary(m.nodes[n].r, m.nodes[n].z)});
  }
  const DofMap dofs(ids, "T", fixed);
  const Assembler assembler(dofs, m.elements.size(), [&m](std::size_t e) {
    return std::span<const int>(m.elements[e].nodes.data(), static_cast<std::size_t>(m.elements[e].node_count));
  });
  std::vector<double> values(static_cast<std::size_t>(assembler.pattern().nnz()), 0.0);
  std::vector<double> rhs(static_cast<std::size_t>(dofs.size()), 0.0);
  const Eigen::Vector4d no_source = Eigen::Vector4d::Zero();
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Element& el = m.elements[e];
    ConductionData d;
    d.node_count = el.node_count;
    d.x = corner_coordinates(m, el.nodes, el.node_count);
    d.analysis = m.analysis;
    d.thickness = m.thickness;
    d.k = k;
    const Eigen::Matrix4d K = conduction_matrix(d);
    assembler.add(e, ElementBlock::of(K, no_source), {values, rhs});
  }
  SparseCholesky cholesky(assembler.pattern(), dofs.node_of_equation());
  cholesky.factorize(values);
  std::vector<double> x(rhs.size());
  cholesky.solve(rhs, x);
  std::vector<double> T(m.nodes.size());
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) {
    const Index eq = dofs.equation(n, 0);
    T[n] = eq >= 0 ? x[eq] : dofs.prescribed(n, 0);
  }
  return T;
}

void expect_reproduced(AnalysisType analysis, const Conductivity& k, const std::function<double(double, double)>& field) {
  const Model m = distorted_patch(analysis);
  const std::vector<double> T = solve_temperature(m, k, field);
  int interior = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    interior += on_boundary(m.nodes[n]) ? 0 : 1;
    // The field's scale is 100 degrees: round-off.
    EXPECT_NEAR(T[n], field(m.nodes[n].r, m.nodes[n].z), 1e-12) << "node " << m.nodes[n].id;
  }
  EXPECT_EQ(interior, 6);
}

TEST(ConductionPatch, PlaneIsotropicLinearField) {
  expect_reproduced(AnalysisType::plane_stress, {2.0, 2.0, 0.0}, [](double r, double z) { return 20.0 + 30.0 * r - 45.0 * z; });
}

TEST(ConductionPatch, PlaneRotatedOrthotropicLinearField) {
  expect_reproduced(AnalysisType::plane_strain, {3.0, 0.4, 33.0}, [](double r, double z) { return -5.0 + 41.0 * r + 17.0 * z; });
}

TEST(ConductionPatch, AxisymmetricIsotropicAxialField) {
  expect_reproduced(AnalysisType::axisymmetric, {1.5, 1.5, 0.0}, [](double, double z) { return 80.0 - 60.0 * z; });
}

TEST(ConductionPatch, AxisymmetricOrthotropicAlongAxesAxialField) {
  expect_reproduced(AnalysisType::axisymmetric, {0.3, 2.5, 0.0}, [](double, double z) { return 10.0 + 70.0 * z; });
  expect_reproduced(AnalysisType::axisymmetric, {0.3, 2.5, 90.0}, [](double, double z) { return 10.0 + 70.0 * z; });
}

TEST(ConductionPatch, AxisymmetricWeightingMakesAFieldLinearInRadiusNoSolution) {
  // The same boundary values T = 100 r: reproduced in plane; in axisymmetry 100 r is no solution
  // (its (1/r) d/dr (r dT/dr) = 100 / r), so the interior must differ: the 2 pi r weight is in effect.
  const auto field = [](double r, double) { return 100.0 * r; };
  expect_reproduced(AnalysisType::plane_stress, {1.0, 1.0, 0.0}, field);
  const Model m = distorted_patch(AnalysisType::axisymmetric);
  const std::vector<double> T = solve_temperature(m, {1.0, 1.0, 0.0}, field);
  double largest = 0.0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) largest = std::max(largest, std::abs(T[n] - field(m.nodes[n].r, m.nodes[n].z)));
  EXPECT_GT(largest, 0.1);
}

}  // namespace
}  // namespace saasgaps
