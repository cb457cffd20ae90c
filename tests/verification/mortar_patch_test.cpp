// The contact patch test on non-matching meshes, with the mortar rows alone (before they are wired
// into the analysis): two stacked blocks of different materials meeting on a face of 5 graded
// segments against 7, a uniform pressure p on top, the bottom held in z. Every contact row is
// enforced as an equality (the blocks are pressed together) by a dense saddle-point solve,
//   [K  -C^T] [u     ]   [f      ]
//   [C   0  ] [lambda] = [-g0 / D],   C = the rows / D_j,
// and every element's stress must be (0, -p, 0) and every contact pressure lambda_j / D_j = p to
// 1e-8 relative, in plane stress, plane strain and axisymmetry, either side as the slave, touching or
// with an initial interference. Node-to-segment rows on the same meshes do not pass.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "solver/assembly/element_data.hpp"
#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_kernel.hpp"
#include "solver/materials/material.hpp"
#include "solver/mortar/mortar_coupling.hpp"
#include "support/stacked_blocks.hpp"

namespace saasgaps {
namespace {

using testing::BlockFace;
using testing::StackedBlocks;

constexpr double pressure = 250.0;
constexpr int layers = 3;

StackedBlocks blocks(AnalysisType analysis, double gap) {
  return testing::stacked_blocks(analysis, 1.0, 2.0, 1.0, gap, BlockFace{5, 1.3}, BlockFace{7, 0.75}, layers);
}

/// Contact rows as dense constraints: C (one row per contact row, over 2 x nodes) and its g0, both
/// divided by the row's weight D_j (gaps in length units, multipliers in force units).
struct Constraints {
  Eigen::MatrixXd C;
  Eigen::VectorXd g0;
  Eigen::VectorXd weight;
};

Constraints mortar_constraints(const StackedBlocks& b, bool slave_below) {
  const Model& m = b.model;
  const MortarRows rows = mortar_rows(m.nodes, {m.analysis, m.thickness},
                                      contact_surface(m, slave_below ? b.lower_top : b.upper_bottom),
                                      contact_surface(m, slave_below ? b.upper_bottom : b.lower_top));
  Constraints c{Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(2 * m.nodes.size())),
                Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.size())),
                Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.size()))};
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    c.weight[i] = rows.weight[r];
    c.g0[i] = rows.g0[r] / rows.weight[r];
    for (std::size_t e = rows.start[r]; e < rows.start[r + 1]; ++e) {
      c.C(i, 2 * rows.node[e]) += rows.coefficient[e].x() / rows.weight[r];
      c.C(i, 2 * rows.node[e] + 1) += rows.coefficient[e].y() / rows.weight[r];
    }
  }
  return c;
}

/// Single-pass node-to-segment rows: each node of the lower face against the upper face's segment
/// above it, weighted by its consistent share of the lower face (for the pressures).
Constraints node_to_segment_constraints(const StackedBlocks& b) {
  const Model& m = b.model;
  auto x = [&](int i) { return Vec2(m.nodes[static_cast<std::size_t>(i)].r, m.nodes[static_cast<std::size_t>(i)].z); };
  const int n = b.lower.ni + 1;
  Constraints c{Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(2 * m.nodes.size())), Eigen::VectorXd::Zero(n),
                Eigen::VectorXd::Zero(n)};
  for (int i = 0; i < n; ++i) {
    const int j = b.lower.at(i, layers);
    c.C(i, 2 * j + 1) = -1.0;
    for (const auto& e : b.upper_bottom) {
      const double r0 = x(e[0]).x();
      const double r1 = x(e[1]).x();
      const double eta = (x(j).x() - r0) / (r1 - r0);
      if (eta < 0.0 || eta > 1.0) continue;
      c.C(i, 2 * e[0] + 1) = 1.0 - eta;
      c.C(i, 2 * e[1] + 1) = eta;
      c.g0[i] = x(e[0]).y() - x(j).y();
      break;
    }
  }
  for (const auto& e : b.lower_top) {
    const auto loads = edge_traction_loads(x(e[0]), x(e[1]), Vec2(0.0, 1.0), m.analysis, m.thickness);
    for (int k = 0; k < 2; ++k) {
      for (int i = 0; i < n; ++i) {
        if (b.lower.at(i, layers) == e[static_cast<std::size_t>(k)]) c.weight[i] += loads[static_cast<std::size_t>(k)].y();
      }
    }
  }
  return c;
}

struct Outcome {
  double stress_error = 0.0;    ///< max over elements and components of |sigma - (0, -p, 0)| / p
  double pressure_error = 0.0;  ///< max over rows of |lambda_j / D_j - p| / p
  double residual_gap = 0.0;    ///< max |g_j| after the solve (length)
};

Outcome pressed(const StackedBlocks& b, const Constraints& c) {
  const Model& m = b.model;
  const auto N = static_cast<Eigen::Index>(2 * m.nodes.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(N);
  std::vector<ElementData> data;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Element& el = m.elements[e];
    const Material& mat = m.materials[static_cast<std::size_t>(el.material)];
    const Constitutive law = constitutive(interpolate(mat.table, 0.0, mat.isotropic), m.analysis, el.angle_deg);
    data.push_back(solid_element_data(m, e, law));
    const ElementMatrices em = element_matrices(data.back());
    for (int a = 0; a < 2 * el.node_count; ++a) {
      for (int bb = 0; bb < 2 * el.node_count; ++bb) {
        K(2 * el.nodes[static_cast<std::size_t>(a / 2)] + a % 2, 2 * el.nodes[static_cast<std::size_t>(bb / 2)] + bb % 2) +=
            em.K(a, bb);
      }
    }
  }
  auto x = [&](int i) { return Vec2(m.nodes[static_cast<std::size_t>(i)].r, m.nodes[static_cast<std::size_t>(i)].z); };
  for (const auto& e : testing::row_edges(b.upper, layers)) {
    const auto loads = edge_traction_loads(x(e[0]), x(e[1]), Vec2(0.0, -pressure), m.analysis, m.thickness);
    for (std::size_t k = 0; k < 2; ++k) f.segment<2>(2 * e[k]) += loads[k];
  }
  // Held: the lower block's bottom in z; in plane analyses one node of each block in r.
  std::vector<bool> held(static_cast<std::size_t>(N), false);
  for (int i = 0; i <= b.lower.ni; ++i) held[static_cast<std::size_t>(2 * b.lower.at(i, 0) + 1)] = true;
  if (m.analysis != AnalysisType::axisymmetric) {
    held[static_cast<std::size_t>(2 * b.lower.at(0, 0))] = true;
    held[static_cast<std::size_t>(2 * b.upper.at(0, layers))] = true;
  }
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < N; ++i) {
    if (!held[static_cast<std::size_t>(i)]) free.push_back(i);
  }
  const auto F = static_cast<Eigen::Index>(free.size());
  const Eigen::Index R = c.C.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(F + R, F + R);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(F + R);
  // The constraint block scaled like K (lambda = scale x the solved multiplier): unscaled, its Schur
  // complement C K^-1 C^T ~ 1 / |K| falls below the pivoting threshold in axisymmetry.
  const double scale = K.diagonal().maxCoeff();
  for (Eigen::Index i = 0; i < F; ++i) {
    for (Eigen::Index j = 0; j < F; ++j) A(i, j) = K(free[i], free[j]);
    for (Eigen::Index r = 0; r < R; ++r) {
      A(i, F + r) = -scale * c.C(r, free[i]);
      A(F + r, i) = scale * c.C(r, free[i]);
    }
    rhs[i] = f[free[i]];
  }
  rhs.tail(R) = -scale * c.g0;
  const Eigen::VectorXd solution = A.fullPivLu().solve(rhs);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(N);
  for (Eigen::Index i = 0; i < F; ++i) u[free[i]] = solution[i];

  Outcome out;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Element& el = m.elements[e];
    Vec8 ue = Vec8::Zero();
    for (int a = 0; a < 2 * el.node_count; ++a) ue[a] = u[2 * el.nodes[static_cast<std::size_t>(a / 2)] + a % 2];
    const Vec4 s = element_state(data[e], std::span<const double>(ue.data(), 8)).stress;
    for (const double d : {s[rr], s[zz] + pressure, s[rz]}) out.stress_error = std::max(out.stress_error, std::abs(d) / pressure);
  }
  for (Eigen::Index r = 0; r < R; ++r) {
    out.pressure_error = std::max(out.pressure_error, std::abs(scale * solution[F + r] / c.weight[r] - pressure) / pressure);
    out.residual_gap = std::max(out.residual_gap, std::abs(c.g0[r] + c.C.row(r).dot(u)));
  }
  return out;
}

TEST(MortarPatchTest, UniformPressureCrossesNonMatchingMeshesUnchanged) {
  for (const testing::PatchCase& c : testing::patch_cases()) {
    SCOPED_TRACE(c.name);
    const StackedBlocks b = blocks(c.analysis, c.gap);
    const Outcome out = pressed(b, mortar_constraints(b, c.lower_is_a));
    EXPECT_LT(out.stress_error, 1e-8);
    EXPECT_LT(out.pressure_error, 1e-8);
    EXPECT_LT(out.residual_gap, 1e-12);
  }
}

TEST(MortarPatchTest, NodeToSegmentFailsIt) {
  // The same meshes with each lower node held on the upper segment above it: the upper face's nodes
  // get the lower nodes' forces split by the segment's linear weights, not the consistent load of a
  // uniform pressure, so the stress cannot stay uniform.
  for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
    const StackedBlocks b = blocks(analysis, 0.0);
    const Outcome out = pressed(b, node_to_segment_constraints(b));
    EXPECT_GT(out.stress_error, 0.05) << static_cast<int>(analysis);
    EXPECT_LT(out.residual_gap, 1e-12);
  }
}

}  // namespace
}  // namespace saasgaps
