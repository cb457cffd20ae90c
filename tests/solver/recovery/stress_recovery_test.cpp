// Recovered nodal stresses and the error estimate (solver/recovery) on patch tests: a distorted
// 4 x 4 patch of every family (interior corners off the grid), its boundary moved by a linear
// displacement field. The solution is then the linear field, every sampled stress the constant
// D eps, and the recovery must give that constant at every node (to round-off) with an error
// estimate of zero; a two-material block keeps each material's stress on its side of the interface.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "solver/analysis/analysis.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/recovery/patch_recovery.hpp"
#include "solver/recovery/sampling_points.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

constexpr double E = 200.0e3, nu = 0.3;
constexpr int cells = 4;

struct Case {
  ElementType type;
  Integration integration;
  const char* name;
};

/// The corner (i, j) of the distorted grid on [0, 4] x [0, 4]: interior corners moved by up to 0.2.
Vec2 corner(int i, int j) {
  Vec2 x(i, j);
  if (i > 0 && i < cells && j > 0 && j < cells) x += Vec2(0.2 * std::sin(1.7 * i + 2.3 * j), 0.15 * std::cos(1.1 * i - 0.7 * j));
  return x;
}

/// A grid of one family (triangles: each cell split along its (i, j)-(i+1, j+1) diagonal), straight
/// edges, mid-side nodes half-way, quad9 centres at the mean of their corners. materials: the
/// material index of cell (i, j).
Model grid(const Case& c, const std::function<int(int, int)>& material_of = [](int, int) { return 0; }) {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.thickness = 1.0;
  m.materials.push_back(testing::isotropic_material(1, E, nu));
  m.materials.push_back(testing::isotropic_material(2, 3.0 * E, 0.2));
  std::map<std::tuple<int, int, int, int>, int> made;  // nodes by their points' sum in halves
  const auto node = [&](const Vec2& x, std::tuple<int, int, int, int> key) {
    const auto found = made.find(key);
    if (found != made.end()) return found->second;
    const int index = static_cast<int>(m.nodes.size());
    m.nodes.push_back({index + 1, x.x(), x.y()});
    made[key] = index;
    return index;
  };
  const auto at = [&](int i, int j) { return node(corner(i, j), {i, j, i, j}); };
  const auto mid = [&](int i0, int j0, int i1, int j1) {
    const auto key = std::make_tuple(std::min(i0, i1), std::min(j0, j1), std::max(i0, i1), std::max(j0, j1));
    const auto a = std::make_pair(i0, j0) < std::make_pair(i1, j1) ? std::make_pair(i0, j0) : std::make_pair(i1, j1);
    const auto b = std::make_pair(i0, j0) < std::make_pair(i1, j1) ? std::make_pair(i1, j1) : std::make_pair(i0, j0);
    return node(0.5 * (corner(a.first, a.second) + corner(b.first, b.second)), key);
  };
  const ElementFamily& fam = family(c.type);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const auto add = [&](std::vector<int> nodes) {
        Element el;
        el.id = static_cast<int>(m.elements.size()) + 1;
        el.type = c.type;
        el.integration = c.integration;
        el.material = material_of(i, j);
        el.node_count = static_cast<int>(nodes.size());
        for (std::size_t a = 0; a < nodes.size(); ++a) el.nodes[a] = nodes[a];
        m.elements.push_back(el);
      };
      if (fam.cell == CellShape::triangle) {
        if (fam.quadratic()) {
          add({at(i, j), at(i + 1, j), at(i + 1, j + 1), mid(i, j, i + 1, j), mid(i + 1, j, i + 1, j + 1), mid(i, j, i + 1, j + 1)});
          add({at(i, j), at(i + 1, j + 1), at(i, j + 1), mid(i, j, i + 1, j + 1), mid(i + 1, j + 1, i, j + 1), mid(i, j + 1, i, j)});
        } else {
          add({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          add({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
      } else if (fam.quadratic()) {
        std::vector<int> n{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), mid(i, j, i + 1, j),
                           mid(i + 1, j, i + 1, j + 1), mid(i, j + 1, i + 1, j + 1), mid(i, j, i, j + 1)};
        if (fam.node_count == 9) {
          const Vec2 centre = 0.25 * (corner(i, j) + corner(i + 1, j) + corner(i + 1, j + 1) + corner(i, j + 1));
          n.push_back(node(centre, {i, j, i + 1, j + 1}));
        }
        add(n);
      } else {
        add({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  m.loads.node_temperature.assign(m.nodes.size(), 0.0);
  return m;
}

/// u = (a r + b z + c, d r + e z + f), prescribed on every boundary node.
Vec2 linear_field(const Vec2& x) {
  return Vec2(1e-3 * x.x() - 4e-4 * x.y() + 2e-3, 6e-4 * x.x() - 8e-4 * x.y() - 1e-3);
}

void prescribe_boundary(Model& m) {
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const Vec2 x(m.nodes[n].r, m.nodes[n].z);
    const bool boundary = x.x() < 1e-12 || x.y() < 1e-12 || x.x() > cells - 1e-12 || x.y() > cells - 1e-12;
    if (boundary) testing::constrain(m, static_cast<int>(n), linear_field(x).x(), linear_field(x).y());
  }
}

/// The plane-stress stress of the linear field in material (E, nu).
Vec4 exact_stress(double e, double v) {
  const double er = 1e-3, ez = -8e-4, g = -4e-4 + 6e-4;
  const double c = e / (1.0 - v * v);
  return Vec4(c * (er + v * ez), c * (ez + v * er), e / (2.0 * (1.0 + v)) * g, 0.0);
}

class RecoveryPatch : public ::testing::TestWithParam<Case> {};

TEST_P(RecoveryPatch, ALinearFieldIsRecoveredExactlyWithNoError) {
  Model m = grid(GetParam());
  prescribe_boundary(m);
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const Vec4 exact = exact_stress(E, nu);
  ASSERT_FALSE(s.recovered.empty());
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    ASSERT_EQ(s.recovered.side_count(n), 1) << "node " << n + 1;
    EXPECT_LE((s.recovered.mean(n) - exact).norm(), 1e-9 * exact.norm()) << "node " << n + 1 << ": "
                                                                         << s.recovered.mean(n).transpose();
  }
  ASSERT_TRUE(s.error_estimate.has_value());
  EXPECT_GT(s.error_estimate->energy_norm, 0.0);
  EXPECT_LE(s.error_estimate->error, 1e-9 * s.error_estimate->energy_norm);
  EXPECT_LE(s.error_estimate->relative, 1e-9);
  double sum = 0.0;
  for (const ElementResult& e : s.elements) sum += e.error * e.error;
  EXPECT_NEAR(std::sqrt(sum), s.error_estimate->error, 1e-12 * s.error_estimate->energy_norm);
}

TEST_P(RecoveryPatch, EachMaterialKeepsItsOwnSideOfAnInterface) {
  // Left half material 0, right half material 1 (3 E, nu 0.2), every node moved by the linear field:
  // the same strain gives each material its own stress, the interface nodes hold both, and nodes[]
  // shows their mean.
  Model m = grid(GetParam(), [](int i, int) { return i < cells / 2 ? 0 : 1; });
  // (All but one interior node of material 0, which its equilibrium puts on the field: the solver
  // wants an unknown.)
  const Vec2 free = corner(1, 2);
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const Vec2 x(m.nodes[n].r, m.nodes[n].z);
    if ((x - free).norm() < 1e-12) continue;
    testing::constrain(m, static_cast<int>(n), linear_field(x).x(), linear_field(x).y());
  }
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const std::array<Vec4, 2> exact{exact_stress(E, nu), exact_stress(3.0 * E, 0.2)};
  int interface = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    ASSERT_GE(s.recovered.side_count(n), 1);
    if (s.recovered.side_count(n) == 2) {
      ++interface;
      EXPECT_LE((s.recovered.mean(n) - 0.5 * (exact[0] + exact[1])).norm(), 1e-9 * exact[1].norm());
    }
    for (int k = 0; k < 2; ++k) {
      if (s.recovered.side(n, k) >= 0) {
        EXPECT_LE((s.recovered.at(n, k) - exact[static_cast<std::size_t>(k)]).norm(), 1e-9 * exact[1].norm())
            << "node " << n + 1 << " material " << k;
      }
    }
  }
  // The corners of the interface line, and its mid-side nodes for the quadratic families.
  EXPECT_EQ(interface, family(GetParam().type).quadratic() ? 2 * cells + 1 : cells + 1);
  EXPECT_LE(s.error_estimate->relative, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Families, RecoveryPatch,
                         ::testing::Values(Case{ElementType::saas, Integration::full, "saas"},
                                           Case{ElementType::tri3, Integration::full, "tri3"},
                                           Case{ElementType::tri6, Integration::full, "tri6"},
                                           Case{ElementType::quad8, Integration::full, "quad8_full"},
                                           Case{ElementType::quad8, Integration::reduced, "quad8_reduced"},
                                           Case{ElementType::quad9, Integration::full, "quad9_full"},
                                           Case{ElementType::quad4i, Integration::full, "quad4i"}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(SamplingPoints, TheTwoByTwoValuesOfANineByNineRuleInterpolateABiquadratic) {
  // W maps any biquadratic's values at the 3 x 3 points to its values at the 2 x 2 points.
  const auto f = [](double x, double y) { return 1.0 + 2.0 * x - y + 0.5 * x * x * y - 0.25 * x * x * y * y; };
  const auto nine = [] {
    std::array<std::array<double, 2>, 9> p{};
    const double a = std::sqrt(0.6);
    const std::array<double, 3> s{-a, 0.0, a};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) p[static_cast<std::size_t>(i + 3 * j)] = {s[static_cast<std::size_t>(i)], s[static_cast<std::size_t>(j)]};
    return p;
  }();
  const auto& W = gauss3_to_gauss2();
  const double g = 1.0 / std::sqrt(3.0);
  const std::array<std::array<double, 2>, 4> four{{{-g, -g}, {g, -g}, {-g, g}, {g, g}}};
  for (std::size_t q = 0; q < 4; ++q) {
    double v = 0.0;
    for (std::size_t p = 0; p < 9; ++p) v += W[q][p] * f(nine[p][0], nine[p][1]);
    EXPECT_NEAR(v, f(four[q][0], four[q][1]), 1e-13);
  }
}

}  // namespace
}  // namespace saasgaps
