// The assembly layer for any field: DofMap numbering with any number of components, the Assembler's
// scatter (element blocks of any size, prescribed values lifted to the right-hand side) against a
// dense sum, and extra couplings (a constraint row across nodes no element joins) in the pattern.
#include "solver/assembly/assembler.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "solver/assembly/dof_map.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/thermal/conduction_kernel.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

TEST(DofMap, NumbersNodeByNodeComponentsInOrderSkippingPrescribed) {
  Model m;
  for (int id : {7, 8, 9}) m.nodes.push_back({id, 0.0, 0.0});
  m.constraints = {{1, 0.5, std::nullopt}, {2, 0.0, -0.25}};
  const DofMap u(m);
  EXPECT_EQ(u.components(), 2);
  EXPECT_EQ(u.size(), 3);
  EXPECT_EQ(u.equation(0, 0), 0);
  EXPECT_EQ(u.equation(0, 1), 1);
  EXPECT_EQ(u.equation(1, 0), DofMap::prescribed_dof);
  EXPECT_EQ(u.equation(1, 1), 2);
  EXPECT_EQ(u.equation(2, 0), DofMap::prescribed_dof);
  EXPECT_EQ(u.prescribed(1, 0), 0.5);
  EXPECT_EQ(u.prescribed(2, 1), -0.25);
  EXPECT_EQ(u.node_dof(2).node_id, 8);
  EXPECT_EQ(u.node_dof(2).direction, 'z');
  EXPECT_EQ(u.node_of_equation(), (std::vector<Index>{0, 0, 1}));

  const std::vector<int> ids{7, 8, 9};
  const std::vector<DofMap::Prescribed> fixed{{1, 0, 300.0}};
  const DofMap T(ids, "T", fixed);
  EXPECT_EQ(T.size(), 2);
  EXPECT_EQ(T.equation(2, 0), 1);
  EXPECT_EQ(T.prescribed(1, 0), 300.0);
  EXPECT_EQ(T.node_dof(1).node_id, 9);
  EXPECT_EQ(T.node_dof(1).direction, 'T');
  std::array<Index, 3> eq{};
  T.equations(std::vector<int>{2, 1, 0}, eq);
  EXPECT_EQ(eq, (std::array<Index, 3>{1, DofMap::prescribed_dof, 0}));
}

/// A 2 x 2 grid of quads with the lower-left quad split in two triangles (5 elements, 9 nodes).
Model small_mesh() {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {testing::isotropic_material(1, 1.0, 0.3)};
  testing::add_grid(m, 2, 2, [](double s, double t) { return Vec2(1.0 + s + 0.1 * t * t, t + 0.2 * s * t); }, 0);
  Element& quad = m.elements[0];
  Element second = quad;
  second.id = 50;
  second.node_count = 3;
  second.nodes = {quad.nodes[0], quad.nodes[2], quad.nodes[3], -1};
  quad.node_count = 3;
  quad.nodes[3] = -1;
  m.elements.push_back(second);
  return m;
}

std::span<const int> nodes_of(const Model& m, std::size_t e) {
  return {m.elements[e].nodes.data(), static_cast<std::size_t>(m.elements[e].node_count)};
}

Eigen::Matrix4d conductance(const Model& m, std::size_t e) {
  ConductionData d;
  d.node_count = m.elements[e].node_count;
  for (int a = 0; a < d.node_count; ++a) d.x[a] = Vec2(m.nodes[m.elements[e].nodes[a]].r, m.nodes[m.elements[e].nodes[a]].z);
  d.k = {2.0, 0.5, 25.0};
  return conduction_matrix(d);
}

TEST(Assembler, ScalarScatterEqualsTheDenseSumWithPrescribedValuesLifted) {
  const Model m = small_mesh();
  std::vector<int> ids;
  for (const Node& n : m.nodes) ids.push_back(n.id);
  const std::vector<DofMap::Prescribed> fixed{{0, 0, 10.0}, {4, 0, 0.0}, {8, 0, -3.0}};
  const DofMap dofs(ids, "T", fixed);
  const Assembler assembler(dofs, m.elements.size(), [&m](std::size_t e) { return nodes_of(m, e); });
  std::vector<double> values(static_cast<std::size_t>(assembler.pattern().nnz()), 0.0);
  std::vector<double> rhs(static_cast<std::size_t>(dofs.size()), 0.0);

  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs.size(), dofs.size());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Eigen::Matrix4d ke = conductance(m, e);
    const Eigen::Vector4d fe(1.0 + static_cast<double>(e), 2.0, -1.0, 0.5 * static_cast<double>(e));  // any source vector
    assembler.add(e, ElementBlock::of(ke, fe), {values, rhs});
    const std::span<const int> nodes = nodes_of(m, e);
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const Index i = dofs.equation(nodes[a], 0);
      if (i < 0) continue;
      f[i] += fe[a];
      for (std::size_t b = 0; b < nodes.size(); ++b) {
        const Index j = dofs.equation(nodes[b], 0);
        if (j >= 0) K(i, j) += ke(a, b); else f[i] -= ke(a, b) * dofs.prescribed(nodes[b], 0);
      }
    }
  }
  const CscPattern& p = assembler.pattern();
  Eigen::MatrixXd sparse = Eigen::MatrixXd::Zero(p.n, p.n);
  for (Index j = 0; j < p.n; ++j) {
    for (Index k = p.colptr[j]; k < p.colptr[j + 1]; ++k) sparse(p.rowind[k], j) = sparse(j, p.rowind[k]) = values[k];
  }
  EXPECT_LT((sparse - K).norm(), 1e-14 * K.norm());
  EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(rhs.data(), dofs.size()) - f).norm(), 1e-14 * f.norm());
}

/// Cliques are looked up on the cores in ranges (index_ranges.hpp) when there are many: on a grid of
/// 10,000 quads with a prescribed row, every clique's positions are still those find() gives.
TEST(Assembler, ManyCliquesSplitAmongTheCoresGetTheirPositions) {
  Model m;
  testing::add_grid(m, 100, 100, [](double x, double y) { return Vec2(1.0 + x, y); }, 0);
  std::vector<int> ids;
  std::vector<DofMap::Prescribed> fixed;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    ids.push_back(m.nodes[n].id);
    if (m.nodes[n].z == 0.0) fixed.push_back({static_cast<int>(n), 0, 0.5});
  }
  const DofMap dofs(ids, "T", fixed);
  ASSERT_GT(range_count(m.elements.size()), 1U) << "the machine has one core: the split is not exercised";
  const Assembler assembler(dofs, m.elements.size(), [&m](std::size_t e) { return nodes_of(m, e); });
  for (std::size_t c = 0; c < assembler.clique_count(); ++c) {
    const std::span<const Index> eq = assembler.equations(c);
    const std::span<const Index> positions = assembler.positions(c);
    ASSERT_EQ(positions.size(), eq.size() * (eq.size() + 1) / 2);
    std::size_t k = 0;
    for (std::size_t b = 0; b < eq.size(); ++b) {
      for (std::size_t a = 0; a <= b; ++a, ++k) {
        const Index expected = eq[a] >= 0 && eq[b] >= 0 ? assembler.pattern().find(eq[a], eq[b]) : -1;
        ASSERT_EQ(positions[k], expected) << "clique " << c;
        if (eq[a] >= 0 && eq[b] >= 0) {
          ASSERT_GE(positions[k], 0);
        }
      }
    }
  }
}

TEST(Assembler, ExtraCouplingsOfAnyWidthEnterThePatternAndTakeValues) {
  const Model m = small_mesh();
  const DofMap dofs(m);  // nothing prescribed: 18 equations
  // Nodes 0 and 8 are opposite corners: no element joins them. A row across nodes 0, 8 and 5
  // (six equations), another across 0 and 8 only (z components), with a prescribed-like -1 skipped.
  Cliques rows;
  std::array<Index, 6> wide{};
  dofs.equations(std::vector<int>{0, 8, 5}, wide);
  rows.add(wide);
  rows.add(std::vector<Index>{dofs.equation(0, 1), DofMap::prescribed_dof, dofs.equation(8, 1)});

  const Assembler without(dofs, m.elements.size(), [&m](std::size_t e) { return nodes_of(m, e); });
  const Assembler with(dofs, m.elements.size(), [&m](std::size_t e) { return nodes_of(m, e); }, rows);
  EXPECT_EQ(without.pattern().find(dofs.equation(0, 0), dofs.equation(8, 1)), -1);
  EXPECT_GE(with.pattern().find(dofs.equation(0, 0), dofs.equation(8, 1)), 0);
  EXPECT_GT(with.pattern().nnz(), without.pattern().nnz());
  ASSERT_EQ(with.clique_count(), m.elements.size() + 2);

  // The row's block g g^T (a penalty row) lands at the row's positions.
  const std::size_t row = m.elements.size();
  Eigen::Matrix<double, 6, 1> g;
  g << 1.0, -2.0, 0.5, 3.0, -1.0, 0.25;
  const Eigen::Matrix<double, 6, 6> block = g * g.transpose();
  const Eigen::Matrix<double, 6, 1> no_load = Eigen::Matrix<double, 6, 1>::Zero();
  std::vector<double> values(static_cast<std::size_t>(with.pattern().nnz()), 0.0);
  std::vector<double> rhs(static_cast<std::size_t>(dofs.size()), 0.0);
  with.add(row, ElementBlock::of(block, no_load), {values, rhs});
  for (int a = 0; a < 6; ++a) {
    for (int b = 0; b < 6; ++b) {
      EXPECT_EQ(values[with.pattern().find(wide[a], wide[b])], block(a, b)) << a << ", " << b;
    }
  }
  EXPECT_EQ(with.positions(row + 1).size(), 6u);  // 3 x 3 upper triangle
  EXPECT_EQ(with.positions(row + 1)[1], -1);      // (0, 1): the skipped entry
}

}  // namespace
}  // namespace saasgaps
