// Assembly: the sparse system equals the dense sum of the element matrices, and patching only the
// gap entries gives the same matrix as assembling everything afresh.
#include "solver/assembly/stiffness_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/gaps/gap_closure.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

/// Two blocks side by side with a row of gap elements between them, one corner of each pinned.
Model two_blocks_with_gap() {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3, 1e-5)};
  const testing::Grid left = testing::add_grid(m, 3, 2, [](double s, double t) { return Vec2(s, t); }, 0);
  const testing::Grid right = testing::add_grid(m, 3, 2, [](double s, double t) { return Vec2(1.01 + s, t); }, 0);
  std::vector<int> a, b;
  for (int j = 0; j <= 2; ++j) {
    a.push_back(left.at(3, j));
    b.push_back(right.at(0, j));
  }
  // Gap elements need counter-clockwise corners: (left k, right k, right k+1, left k+1).
  m.gaps.emplace();
  m.gaps->initial_modulus = 10.0;
  m.gaps->tensile_schedule = {1.0};
  for (int k = 0; k < 2; ++k) {
    GapElement g;
    g.id = 100 + k;
    g.nodes = {a[k], b[k], b[k + 1], a[k + 1]};
    g.angle_deg = 0.0;
    m.gaps->elements.push_back(g);
  }
  testing::fill_temperatures(m, 50.0);
  testing::constrain(m, left.at(0, 0), 0.0, 0.0);
  testing::constrain(m, left.at(0, 2), 0.0, std::nullopt);
  testing::constrain(m, right.at(3, 0), 0.002, 0.0);  // a nonzero prescribed value too
  m.loads.nodal_forces.push_back({right.at(3, 2), -50.0, 10.0});
  return m;
}

Eigen::MatrixXd dense_of(const StiffnessSystem& s) {
  const CscPattern& p = s.pattern();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(p.n, p.n);
  for (Index j = 0; j < p.n; ++j) {
    for (Index k = p.colptr[j]; k < p.colptr[j + 1]; ++k) K(p.rowind[k], j) = K(j, p.rowind[k]) = s.values()[k];
  }
  return K;
}

/// Dense assembly straight from the element kernels and the DOF map.
void dense_assembly(const Model& m, const DofMap& dofs, const LawOf& solid, const LawOf& gap, Eigen::MatrixXd& K,
                    Eigen::VectorXd& f) {
  K = Eigen::MatrixXd::Zero(dofs.size(), dofs.size());
  f = Eigen::VectorXd::Zero(dofs.size());
  const auto add = [&](std::span<const int> nodes, const ElementMatrices& em) {
    const int count = static_cast<int>(nodes.size());
    std::array<Index, max_element_dofs> eq{};
    dofs.equations(nodes, eq);
    for (int a = 0; a < 2 * count; ++a) {
      if (eq[a] < 0) continue;
      f[eq[a]] += em.f[a];
      for (int b = 0; b < 2 * count; ++b) {
        if (eq[b] >= 0) K(eq[a], eq[b]) += em.K(a, b);
        else f[eq[a]] -= em.K(a, b) * dofs.prescribed(nodes[b / 2], b % 2);
      }
    }
  };
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    add(m.elements[e].node_span(), element_matrices(solid_element_data(m, e, solid(e))));
  }
  for (std::size_t g = 0; g < m.gap_count(); ++g) {
    add(m.gaps->elements[g].node_span(), element_matrices(gap_element_data(m, g, gap(g))));
  }
  for (const NodalForce& nf : m.loads.nodal_forces) {
    if (dofs.equation(nf.node, 0) >= 0) f[dofs.equation(nf.node, 0)] += nf.f_r;
    if (dofs.equation(nf.node, 1) >= 0) f[dofs.equation(nf.node, 1)] += nf.f_z;
  }
}

TEST(StiffnessSystem, SparseAssemblyEqualsTheDenseSumOfElements) {
  const Model m = two_blocks_with_gap();
  const DofMap dofs(m);
  const SolidMaterials materials(m);
  const GapClosure gaps(*m.gaps);
  const MaterialState state = materials.initial();
  GapModuli moduli = gaps.initial();
  const LawOf solid = [&](std::size_t e) { return materials.law(e, state); };
  const LawOf gap = [&](std::size_t g) { return gaps.law(g, moduli, m.analysis); };

  StiffnessSystem system(m, dofs);
  system.assemble_solids(solid);
  system.assemble_gaps(gap);
  Eigen::MatrixXd K;
  Eigen::VectorXd f;
  dense_assembly(m, dofs, solid, gap, K, f);
  EXPECT_LT((dense_of(system) - K).norm(), 1e-9 * K.norm());
  const Eigen::Map<const Eigen::VectorXd> rhs(system.rhs().data(), dofs.size());
  EXPECT_LT((rhs - f).norm(), 1e-9 * f.norm());

  // New gap moduli: patching the gap entries equals assembling from scratch.
  moduli.normal = {5000.0, 70.0};
  moduli.tensile = 3.0;
  system.assemble_gaps(gap);
  StiffnessSystem fresh(m, dofs);
  fresh.assemble_solids(solid);
  fresh.assemble_gaps(gap);
  for (std::size_t k = 0; k < system.values().size(); ++k) EXPECT_EQ(system.values()[k], fresh.values()[k]);
  for (std::size_t k = 0; k < system.rhs().size(); ++k) EXPECT_EQ(system.rhs()[k], fresh.rhs()[k]);
  dense_assembly(m, dofs, solid, gap, K, f);
  EXPECT_LT((dense_of(system) - K).norm(), 1e-9 * K.norm());
}

}  // namespace
}  // namespace saasgaps
